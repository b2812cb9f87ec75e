#pragma once
// The byte format of a checkpoint's payload: a self-describing sequence of tagged values
// (every value carries a one-byte tag: f64, i64, bool, string, list with its length, and named
// sections), doubles stored as their exact IEEE-754 bits, little-endian. A reader that meets
// another tag than it expects, or the end of the bytes, throws CheckpointError saying what it
// expected and where; a restored run is therefore either exact or refused, never half-read.
//
// A model's state is archived by StateCodec<S> (specialise it next to the state type); a state
// type without a codec cannot be checkpointed, and the runner says which model that is before
// anything is written. Codecs for arithmetic types, strings, vectors and sets are here.
#include <cstdint>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <vector>

namespace yardsim::devs {

// A checkpoint cannot be written or read: the message says what and where.
class CheckpointError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class CheckpointWriter {
 public:
  // (value) => appended with its tag
  void f64(double v);
  void i64(std::int64_t v);
  void boolean(bool v);
  void str(std::string_view v);
  // (n) => a list of n values follows
  void list(std::size_t n);
  // (name) => a named section begins (checked by name when read back)
  void section(std::string_view name);
  const std::string& bytes() const { return bytes_; }

 private:
  void raw(const void* p, std::size_t n) { bytes_.append(static_cast<const char*>(p), n); }
  std::string bytes_;
};

class CheckpointReader {
 public:
  // (payload bytes, what they are for messages) => a reader at their start
  explicit CheckpointReader(std::string_view bytes) : bytes_(bytes) {}
  double f64();
  std::int64_t i64();
  bool boolean();
  std::string str();
  // () => the length of the list that follows
  std::size_t list();
  // (name) => the named section begins here, else CheckpointError naming both
  void section(std::string_view name);
  bool atEnd() const { return pos_ == bytes_.size(); }

 private:
  void expect(char tag, std::string_view what);
  void raw(void* p, std::size_t n, std::string_view what);
  std::string_view bytes_;
  std::size_t pos_ = 0;
};

// How a state type S is archived: specialise with
//   static void save(CheckpointWriter&, const S&);  static void load(CheckpointReader&, S&);
template <class S>
struct StateCodec;

template <class S>
concept HasStateCodec = requires(CheckpointWriter& w, CheckpointReader& r, const S& cs, S& s) {
  StateCodec<S>::save(w, cs);
  StateCodec<S>::load(r, s);
};

// (value) => archived through its codec; (reader) => the value read back into v
template <class S>
void save(CheckpointWriter& w, const S& v) {
  StateCodec<S>::save(w, v);
}
template <class S>
void load(CheckpointReader& r, S& v) {
  StateCodec<S>::load(r, v);
}

// A codec over a state's fields: specialise StateCodec<S> as
//   template <> struct StateCodec<S> : FieldCodec<S> {
//     static auto fields(auto& s) { return std::tie(s.a, s.b); } };
template <class S>
struct FieldCodec {
  static void save(CheckpointWriter& w, const S& s) {
    std::apply([&](const auto&... f) { (devs::save(w, f), ...); }, StateCodec<S>::fields(s));
  }
  static void load(CheckpointReader& r, S& s) {
    std::apply([&](auto&... f) { (devs::load(r, f), ...); }, StateCodec<S>::fields(s));
  }
};

template <class T>
requires std::is_arithmetic_v<T> || std::is_enum_v<T>
struct StateCodec<T> {
  static void save(CheckpointWriter& w, const T& v) {
    if constexpr (std::is_same_v<T, bool>)
      w.boolean(v);
    else if constexpr (std::is_floating_point_v<T>)
      w.f64(static_cast<double>(v));
    else
      w.i64(static_cast<std::int64_t>(v));
  }
  static void load(CheckpointReader& r, T& v) {
    if constexpr (std::is_same_v<T, bool>)
      v = r.boolean();
    else if constexpr (std::is_floating_point_v<T>)
      v = static_cast<T>(r.f64());
    else
      v = static_cast<T>(r.i64());
  }
};

template <>
struct StateCodec<std::string> {
  static void save(CheckpointWriter& w, const std::string& v) { w.str(v); }
  static void load(CheckpointReader& r, std::string& v) { v = r.str(); }
};

template <class T, class A>
struct StateCodec<std::vector<T, A>> {
  static void save(CheckpointWriter& w, const std::vector<T, A>& v) {
    w.list(v.size());
    for (const auto& e : v) devs::save(w, e);
  }
  static void load(CheckpointReader& r, std::vector<T, A>& v) {
    v.resize(r.list());
    for (auto& e : v) {
      if constexpr (std::is_same_v<T, bool>) {
        bool b = false;
        devs::load(r, b);
        e = b;
      } else {
        devs::load(r, e);
      }
    }
  }
};

template <class T>
struct StateCodec<std::set<T>> {
  static void save(CheckpointWriter& w, const std::set<T>& v) {
    w.list(v.size());
    for (const auto& e : v) devs::save(w, e);
  }
  static void load(CheckpointReader& r, std::set<T>& v) {
    v.clear();
    for (std::size_t n = r.list(); n > 0; --n) {
      T e{};
      devs::load(r, e);
      v.insert(std::move(e));
    }
  }
};

}  // namespace yardsim::devs
