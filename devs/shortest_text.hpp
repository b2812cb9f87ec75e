#pragma once
// The shortest round-trip text of a double, as std::to_chars(first, last, value) writes it, with a
// quick way for short decimals (a trace's times: 24.975, 0.05).
#include <cstddef>
#include <cstdint>

namespace yardsim::devs {

// 10^0 ... 10^19, the powers of ten below 2^64
inline constexpr std::uint64_t kPowersOfTen[] = {1ULL,
                                                 10ULL,
                                                 100ULL,
                                                 1000ULL,
                                                 10000ULL,
                                                 100000ULL,
                                                 1000000ULL,
                                                 10000000ULL,
                                                 100000000ULL,
                                                 1000000000ULL,
                                                 10000000000ULL,
                                                 100000000000ULL,
                                                 1000000000000ULL,
                                                 10000000000000ULL,
                                                 100000000000000ULL,
                                                 1000000000000000ULL,
                                                 10000000000000000ULL,
                                                 100000000000000000ULL,
                                                 1000000000000000000ULL,
                                                 10000000000000000000ULL};

// Longest text writeShortest writes ("-2.2250738585072014e-308"), with room to spare.
inline constexpr std::size_t kShortestTextSize = 32;

// (number, a buffer of kShortestTextSize chars) => the end of its text written from buf: the same
// bytes as std::to_chars(buf, buf + kShortestTextSize, value) (shortest round trip, the shorter
// of fixed and scientific, fixed on a tie; "nan", "inf"). A value of 0.001 <= |v| < 1e9 with at
// most six decimals is written directly; every other value through std::to_chars
char* writeShortest(char* buf, double value);

// A positive number's shortest round-trip decimal, m 10^e (m = 0: not known)
struct ShortestDecimal {
  std::uint64_t significand = 0;
  int exponent = 0;
};

// (number, a buffer of kShortestTextSize chars) => writeShortest's text, the end returned, and in
// decimal its digits and exponent when value is positive and below 1e15 (Dragonbox's), m = 0
// otherwise
char* writeShortest(char* buf, double value, ShortestDecimal& decimal);

// (m 10^e below 1e15 with m > 0, the shortest decimal of the double it names, a buffer of
// kShortestTextSize chars) => its text in std::to_chars' form, the end returned: fixed when no
// longer than scientific, whole numbers fixed at most five zeros long
char* writeDecimal(char* p, std::uint64_t m, int e);

}  // namespace yardsim::devs
