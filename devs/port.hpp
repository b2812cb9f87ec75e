#pragma once
// Typed ports. A port holds the bag of messages of the current event time; the Simulator
// copies bags along the flattened couplings and clears them after the transitions, so in the
// steady state a message costs a copy and no heap allocation (bags keep their capacity).
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <span>
#include <string>
#include <type_traits>
#include <typeinfo>
#include <utility>
#include <vector>

#include "devs/small_vector.hpp"
#include "devs/trace_format.hpp"

namespace yardsim::devs {

class Model;
class Coupled;

class PortBase {
 public:
  PortBase(Model& owner, std::string&& name, bool isInput)
      : isInput_(isInput), owner_(&owner), name_(std::move(name)) {}
  virtual ~PortBase() = default;
  PortBase(const PortBase&) = delete;
  PortBase& operator=(const PortBase&) = delete;

  const std::string& name() const { return name_; }
  Model& owner() const { return *owner_; }
  bool isInput() const { return isInput_; }
  virtual const std::type_info& type() const = 0;
  // () => "<owner path>.<port name>"
  std::string path() const;

  std::size_t size() const { return count_; }
  bool empty() const { return count_ == 0; }
  // (bag) => empty bag, capacity kept; a bag of small values (Port<T> with kInlineBag<T>, whose
  // capacity is never 0) is its count alone, cleared without a call
  void clear() {
    if (bagCapacity_ != 0)
      count_ = 0;
    else
      clearValues();
  }
  // (this bag, destination ports of its value type) => each destination's bag += this bag, in
  // their order (one call per output port and event time: the loop runs inside the typed port)
  virtual void appendToEach(std::span<PortBase* const> dsts) const = 0;
  // (this bag, dst of the same value type) => dst bag += this bag
  void appendTo(PortBase& dst) const {
    PortBase* const one = &dst;
    appendToEach({&one, 1});
  }
  // (message i) => its JSON form appended to out
  virtual void writeValue(std::string& out, std::size_t i) const = 0;

  // Couplings leaving this port, in the coupled model that declared them (read by flatten).
  std::span<PortBase* const> links() const { return links_.span(); }

 protected:
  std::uint32_t count_ = 0;             // messages in the bag
  std::uint32_t bagCapacity_ : 31 = 0;  // an inline bag's capacity (Port<T>), else 0
  std::uint32_t isInput_ : 1;
  // (a bag kept in a std::vector) => its values destroyed, count 0, capacity kept
  virtual void clearValues() = 0;

 private:
  friend class Coupled;
  Model* owner_;
  std::string name_;
  SmallVector<PortBase*, 1> links_;  // most atomic ports have at most one coupling
};

// Whether a port's bag of T keeps its first messages inside the port, in the bytes of the heap
// pointer it has once it grows (small trivially copyable values: a port's first message then
// takes no heap block); other value types keep their bag in a std::vector.
template <class T>
constexpr bool inlineBag() {
  if (sizeof(T) > sizeof(T*) || alignof(T) > alignof(T*)) return false;
  if (!std::is_trivially_copyable_v<T>) return false;
  return std::is_trivially_default_constructible_v<T>;
}
template <class T>
inline constexpr bool kInlineBag = inlineBag<T>();

template <class T, bool = kInlineBag<T>>
struct BagStorage {
  std::vector<T> values;
};
template <class T>
struct BagStorage<T, true> {
  static constexpr std::uint32_t kInline = sizeof(T*) / sizeof(T);
  union {
    T inside[kInline]{};  // while the capacity is kInline
    T* heap;              // once it is larger
  };
};

template <class T>
class Port : public PortBase {
 public:
  using value_type = T;
  Port(Model& owner, std::string&& name, bool isInput) : PortBase(owner, std::move(name), isInput) {
    if constexpr (kInlineBag<T>) bagCapacity_ = BagStorage<T>::kInline;
  }
  ~Port() override {
    if constexpr (kInlineBag<T>)
      if (onHeap()) std::allocator<T>().deallocate(bag_.heap, bagCapacity_);
  }

  const std::type_info& type() const final { return typeid(T); }
  // () => the messages of this event time
  std::span<const T> values() const { return {data(), count_}; }

  void clearValues() final {
    if constexpr (!kInlineBag<T>) bag_.values.clear();
    count_ = 0;
  }
  void appendToEach(std::span<PortBase* const> dsts) const final {
    // flatten checked the types: every destination is a Port<T>
    if constexpr (kInlineBag<T>) {
      if (count_ == 1) {  // the common bag: one message, read once, stored into each
        const T value = data()[0];
        for (PortBase* d : dsts) static_cast<Port<T>*>(d)->push(value);
        return;
      }
      for (PortBase* d : dsts) {
        const T* from = data();
        for (std::uint32_t i = 0; i < count_; ++i) static_cast<Port<T>*>(d)->push(from[i]);
      }
    } else {
      for (PortBase* d : dsts) {
        auto& to = static_cast<Port<T>&>(*d).bag_.values;
        if (count_ == 1)
          to.push_back(bag_.values.front());  // without a range insert's memmove
        else
          to.insert(to.end(), bag_.values.begin(), bag_.values.end());
        static_cast<Port<T>*>(d)->count_ = static_cast<std::uint32_t>(to.size());
      }
    }
  }
  void writeValue(std::string& out, std::size_t i) const final {
    TraceFormat<T>::write(out, data()[i]);
  }

 protected:
  // (value) => appended to the bag
  template <class V>
  void push(V&& value) {
    if constexpr (kInlineBag<T>) {
      if (count_ == bagCapacity_) [[unlikely]]
        grow();
      (onHeap() ? bag_.heap : bag_.inside)[count_++] = value;
    } else {
      bag_.values.push_back(std::forward<V>(value));
      ++count_;
    }
  }

 private:
  bool onHeap() const { return bagCapacity_ > BagStorage<T>::kInline; }
  const T* data() const {
    if constexpr (kInlineBag<T>)
      return onHeap() ? bag_.heap : bag_.inside;
    else
      return bag_.values.data();
  }
  // (full inline bag) => its messages moved to a heap block of twice the capacity
  void grow() {
    const std::uint32_t cap = 2 * bagCapacity_;
    T* fresh = std::allocator<T>().allocate(cap);
    std::memcpy(static_cast<void*>(fresh), data(), count_ * sizeof(T));
    if (onHeap()) std::allocator<T>().deallocate(bag_.heap, bagCapacity_);
    bag_.heap = fresh;
    bagCapacity_ = cap & 0x7fffffffu;
  }

  BagStorage<T> bag_;
};

template <class T>
class InPort final : public Port<T> {
 public:
  InPort(Model& owner, std::string&& name) : Port<T>(owner, std::move(name), true) {}
};

template <class T>
class OutPort final : public Port<T> {
 public:
  OutPort(Model& owner, std::string&& name) : Port<T>(owner, std::move(name), false) {}
  // (value) => appended to this event time's output bag; call only from an output function
  void add(const T& value) { this->push(value); }
  void add(T&& value) { this->push(std::move(value)); }
};

}  // namespace yardsim::devs
