#pragma once
// The shortest round-trip text of a double, as std::to_chars(first, last, value) writes it, with a
// quick way for short decimals (a trace's times: 24.975, 0.05).
#include <cstddef>

namespace yardsim::devs {

// Longest text writeShortest writes ("-2.2250738585072014e-308"), with room to spare.
inline constexpr std::size_t kShortestTextSize = 32;

// (number, a buffer of kShortestTextSize chars) => the end of its text written from buf: the same
// bytes as std::to_chars(buf, buf + kShortestTextSize, value) (shortest round trip, the shorter
// of fixed and scientific, fixed on a tie; "nan", "inf"). A value of 0.001 <= |v| < 1e9 with at
// most six decimals is written directly; every other value through std::to_chars
char* writeShortest(char* buf, double value);

}  // namespace yardsim::devs
