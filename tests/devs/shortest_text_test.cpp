// writeShortest (devs/shortest_text.hpp) against std::to_chars' shortest round-trip text.
#include "devs/shortest_text.hpp"

#include <bit>
#include <catch2/catch.hpp>
#include <charconv>
#include <cmath>
#include <cstdint>
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
  return a == b;
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
