// appendGeneral6 (devs/general_text.hpp) against printf's "%g" and std::to_chars(general, 6).
#include "devs/general_text.hpp"

#include <bit>
#include <catch2/catch.hpp>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>

#include "support/split_mix.hpp"

using namespace yardsim::devs;

TEST_CASE("appendGeneral6 writes printf's g text for every kind of double") {
  // against snprintf("%g") and std::to_chars(general, 6): random bit patterns (every exponent),
  // random values of a scene's size, ties and near-ties of the sixth digit, powers of ten and
  // their neighbours, the ends of the fixed range, zeros, subnormals and non-finite values
  auto check = [](double v) {
    std::string fast;
    appendGeneral6(fast, v);
    char ref[64];
    std::snprintf(ref, sizeof ref, "%g", v);
    char tc[64];
    const auto [end, ec] = std::to_chars(tc, tc + sizeof tc, v, std::chars_format::general, 6);
    REQUIRE(ec == std::errc());
    if (fast != ref || fast != std::string(tc, end)) {
      INFO("value " << std::hexfloat << v << " fast " << fast << " printf " << ref);
      return false;
    }
    return true;
  };
  std::size_t bad = 0;
  yardsim::test::SplitMix64 next{0x9e3779b97f4a7c15ULL};
  for (int i = 0; i < 200000; ++i) {
    bad += !check(std::bit_cast<double>(next()));
    const double u = static_cast<double>(next() >> 11) * 0x1p-53;  // [0, 1)
    const double e = std::floor(u * 60.0) - 30.0;
    bad += !check((u - 0.5) * std::pow(10.0, e));
  }
  for (int e = -40; e <= 40; ++e) {
    const double p = std::pow(10.0, e);
    for (double m : {1.0, 1.234565, 1.2345650000000001, 9.999995, 9.9999949999, 9.9999950001, 5.0,
                     0.5, 2.5000005, 1.0000005, 1.0000015})
      for (double v : {m * p, std::nextafter(m * p, 0.0), std::nextafter(m * p, 1e300)}) {
        bad += !check(v);
        bad += !check(-v);
      }
  }
  for (int e = -130; e <= 130; ++e)  // every binary exponent of the quick range and past its ends
    for (int i = 0; i < 200; ++i) {
      const double v = std::ldexp(1.0 + static_cast<double>(next() >> 11) * 0x1p-53, e);
      bad += !check(v);
      bad += !check(-v);
    }
  for (int i = -3000; i <= 3000; ++i) {  // integers and short decimals: exact round numbers
    bad += !check(i);
    bad += !check(i / 8.0);
    bad += !check(i * 1000.0);
    bad += !check(i * 0.001);
  }
  for (double v : {0.0,
                   -0.0,
                   99999.95,
                   99999.94999,
                   100000.0,
                   100000.5,
                   999999.4,
                   999999.6,
                   1e-5,
                   9.99999e-5,
                   9.999995e-5,
                   999999.0,
                   999999.5,
                   1e6,
                   123456.5,
                   1e-38,
                   9.99999e37,
                   9.999995e37,
                   1e38,
                   0.0001,
                   0.00099999949,
                   5e-324,
                   2.2250738585072014e-308,
                   1.7976931348623157e308,
                   std::numeric_limits<double>::infinity(),
                   -std::numeric_limits<double>::infinity(),
                   std::numeric_limits<double>::quiet_NaN()})
    bad += !check(v);
  CHECK(bad == 0);
}
