#pragma once
// How a port value or an atomic state is written into a trace: as one JSON value.
// Arithmetic types become numbers, strings become JSON strings, types with operator<<
// become the JSON string of what they print, anything else null. Specialise
// TraceFormat<T> for a richer JSON form.
#include <cmath>
#include <concepts>
#include <cstdint>
#include <cstdio>
#include <ostream>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>

namespace yardsim::devs {

// (text) => text appended to out as a quoted, escaped JSON string
void appendJsonString(std::string& out, std::string_view text);
// (number) => JSON number appended to out (non-finite values as null, since JSON has none)
void appendJsonNumber(std::string& out, double value);
// (count) => its decimal digits appended to out
void appendJsonInteger(std::string& out, std::uint64_t value);

template <class T>
concept Streamable = requires(std::ostream& os, const T& v) { os << v; };

template <class T>
struct TraceFormat {
  static void write(std::string& out, const T& value) {
    if constexpr (std::is_same_v<T, bool>) {
      out += value ? "true" : "false";
    } else if constexpr (std::is_arithmetic_v<T>) {
      appendJsonNumber(out, static_cast<double>(value));
    } else if constexpr (std::is_convertible_v<const T&, std::string_view>) {
      appendJsonString(out, std::string_view(value));
    } else if constexpr (Streamable<T>) {
      std::ostringstream os;
      os << value;
      appendJsonString(out, os.str());
    } else {
      out += "null";
    }
  }
};

}  // namespace yardsim::devs
