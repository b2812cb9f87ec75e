// writeShortest (devs/shortest_text.hpp) against std::to_chars' shortest round-trip text, and
// every finite text read back (std::from_chars) to the same double bit for bit.
#include "devs/shortest_text.hpp"

#include <bit>
#include <catch2/catch.hpp>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "support/split_mix.hpp"

using namespace yardsim::devs;

namespace {
// (value) => whether writeShortest's text is std::to_chars' (reported when not)
bool same(double v) {
  char fast[kShortestTextSize];
  const std::string a(fast, writeShortest(fast, v));
  char ref[kShortestTextSize];
  const std::string b(ref, std::to_chars(ref, ref + sizeof ref, v).ptr);
  if (a != b) UNSCOPED_INFO("value " << std::hexfloat << v << ": " << a << " against " << b);
  // (finite value) => its text reads back to the same bits (an independent check of the digits)
  bool back = true;
  if (std::isfinite(v)) {
    double r = 0.0;
    const auto [end, ec] = std::from_chars(a.data(), a.data() + a.size(), r);
    back = ec == std::errc() && end == a.data() + a.size() &&
           std::bit_cast<std::uint64_t>(r) == std::bit_cast<std::uint64_t>(v);
    if (!back)
      UNSCOPED_INFO("value " << std::hexfloat << v << ": " << a << " reads back otherwise");
  }
  return a == b && back;
}
}  // namespace

TEST_CASE("writeShortest writes std::to_chars' shortest text: a trace's times and short decimals") {
  // (times of fixed steps summed as a run sums them, and k dt, for steps of a scene's sizes;
  // decimals of one to eight places at every magnitude of the quick range and past its ends)
  std::size_t bad = 0;
  for (double dt : {1e-3, 2.5e-3, 0.0125, 0.025, 0.05, 0.1, 1.0 / 3.0, 0.02, 0.001953125}) {
    double t = 0.0;
    for (int k = 0; k < 40000; ++k, t += dt) {
      bad += !same(t);
      bad += !same(k * dt);
      bad += !same(-t);
    }
  }
  for (int e = -5; e <= 10; ++e)
    for (int i = 1; i < 20000; i += 7) {
      const double p = std::pow(10.0, e);
      for (double v : {i * p, i / p, i * 1e-6, i * 1e-7, i * 1e-3 + 1e5, i * 1e-8 + 1.0}) {
        bad += !same(v);
        bad += !same(std::nextafter(v, 0.0));
        bad += !same(std::nextafter(v, 1e300));
      }
    }
  CHECK(bad == 0);
}

TEST_CASE("writeShortest writes std::to_chars' text for every kind of double and at its edges") {
  // random bit patterns (every exponent), random values near the quick range, the range's ends
  // and the places where std::to_chars turns to scientific (1e-04, 1e+05) or ties (0.001)
  std::size_t bad = 0;
  yardsim::test::SplitMix64 next{0x13198a2e03707344ULL};
  for (int i = 0; i < 200000; ++i) {
    bad += !same(std::bit_cast<double>(next()));
    const double u = static_cast<double>(next() >> 11) * 0x1p-53;
    bad += !same((u - 0.5) * std::pow(10.0, std::floor(u * 16.0) - 5.0));
  }
  const double edges[] = {
      0.0,         -0.0,          1e-3,      0.0011,    0.0012345,   0.00999,
      0.01,        1e-4,          0.00012,   0.999999,  1.0,         99999.0,
      100000.0,    100000.5,      120000.0,  1234567.0, 999999999.5, 1e9,
      999999999.0, 123456789.125, 9936000.0, 1200000.0, 12000000.0,  100000000.0,
      123000000.0, 1000000.0,     1100000.0, 110000.0,  0.5,         0.1 + 0.2,
      1.0 / 3.0,   2.0 / 3.0,     1e-3 * 3,  HUGE_VAL,  -HUGE_VAL,   std::nan("")};
  for (double v : edges)
    for (double w : {v, -v, std::nextafter(v, 0.0), std::nextafter(v, 2e9)}) bad += !same(w);
  CHECK(bad == 0);
}

TEST_CASE(
    "writeShortest writes std::to_chars' text for 17-digit values, every exponent and subnormals") {
  // Dragonbox's way (everything finite and non-zero below 1e15): random significands at every
  // binary exponent, subnormals, every power of two and its neighbours, m 10^e for m of 1 to 17
  // digits and e from -30 to 20 (the turns between fixed and scientific at each length, trailing
  // zeros of whole numbers), the ends of its range (2^53, 1e15) and the double's extremes
  std::size_t bad = 0;
  yardsim::test::SplitMix64 next{0xa4093822299f31d0ULL};
  for (int e = 0; e < 2047; ++e)
    for (int i = 0; i < 200; ++i) {
      const std::uint64_t bits = (std::uint64_t{static_cast<unsigned>(e)} << 52) | (next() >> 12);
      bad += !same(std::bit_cast<double>(bits));
      bad += !same(-std::bit_cast<double>(bits));
    }
  for (int i = 0; i < 20000; ++i) bad += !same(std::bit_cast<double>(next() >> 12));  // subnormal
  for (int e = -1074; e <= 1023; ++e) {
    const double v = std::ldexp(1.0, e);
    for (double w : {v, -v, std::nextafter(v, 0.0), std::nextafter(v, HUGE_VAL)}) bad += !same(w);
  }
  const std::uint64_t mantissas[] = {1,
                                     7,
                                     12,
                                     125,
                                     1234,
                                     99999,
                                     123456,
                                     1234567,
                                     12345678,
                                     123456789,
                                     1234567891,
                                     12345678912,
                                     123456789123,
                                     1234567891234,
                                     12345678912345,
                                     123456789123456,
                                     1234567891234567,
                                     12345678912345678,
                                     99999999999999999};
  for (const std::uint64_t m : mantissas)
    for (int e = -30; e <= 20; ++e) {
      const double v = static_cast<double>(m) * std::pow(10.0, e);
      for (double w : {v, -v, std::nextafter(v, 0.0), std::nextafter(v, HUGE_VAL)}) bad += !same(w);
    }
  const double edges[] = {0x1p53,
                          0x1p53 + 2.0,
                          0x1p53 - 1.0,
                          1e15,
                          999999999999999.9,
                          1e15 - 0.125,
                          1e16,
                          1e300,
                          1e-300,
                          123456789012345.6,
                          DBL_MAX,
                          DBL_MIN,
                          DBL_TRUE_MIN,
                          5e-324,
                          2.2250738585072009e-308,
                          1e22,
                          1e23,
                          9007199254740993.0,
                          0.1,
                          1.0 - DBL_EPSILON / 2};
  for (double v : edges)
    for (double w : {v, -v, std::nextafter(v, 0.0), std::nextafter(v, HUGE_VAL)}) bad += !same(w);
  for (double v :
       {0.0, -0.0, std::numeric_limits<double>::infinity(),
        -std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN(),
        -std::numeric_limits<double>::quiet_NaN()})
    bad += !same(v);
  CHECK(bad == 0);
}
