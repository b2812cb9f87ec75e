// appendStateHead (devs/trace_state_head.hpp): {"t":...,"steps":...,"x": appended after what the
// string held, t as std::to_chars' shortest text ("null" when JSON cannot hold it), the step count
// in decimal digits: the same head whatever numbers came before (the kept number texts).
#include "devs/trace_state_head.hpp"

#include <bit>
#include <catch2/catch.hpp>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "support/split_mix.hpp"

using namespace yardsim::devs;

namespace {
// (t, steps) => the head put together piece by piece with the standard's conversions: the reference
std::string reference(double t, std::uint64_t steps) {
  std::string s = "{\"t\":";
  char buf[64];
  s += std::isfinite(t) ? std::string(buf, std::to_chars(buf, buf + sizeof buf, t).ptr) : "null";
  s += ",\"steps\":" + std::to_string(steps) + ",\"x\":";
  return s;
}
}  // namespace

TEST_CASE("a DTSS state's head is its time's and step count's text, after what came before") {
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<double> times = {0.0,
                                     -0.0,
                                     0.002,
                                     29.998,
                                     0.30000000000000004,
                                     1e-7,
                                     123456789.125,
                                     1e300,
                                     -2.5,
                                     5e-324,
                                     inf,
                                     -inf,
                                     std::numeric_limits<double>::quiet_NaN()};
  const std::vector<std::uint64_t> counts = {
      0, 1, 9, 10, 99, 100, 14999, 1000000007, std::numeric_limits<std::uint64_t>::max()};
  // (every pair, twice: the second round's times come from the number texts kept) => the head
  // appended to a string that already holds text
  for (int round = 0; round < 2; ++round)
    for (double t : times)
      for (std::uint64_t k : counts) {
        std::string out = "[prefix]";
        appendStateHead(out, t, k);
        CHECK(out == "[prefix]" + reference(t, k));
      }
  // (random bit patterns and grid times, each written twice in a row as a trace does) => the same
  yardsim::test::SplitMix64 rng{21};
  for (int i = 0; i < 20000; ++i) {
    const double t = i % 2 == 0 ? std::bit_cast<double>(rng()) : 0.002 * i;
    const std::uint64_t k = rng() >> (rng() % 64);
    for (int twice = 0; twice < 2; ++twice) {
      std::string out;
      appendStateHead(out, t, k);
      REQUIRE(out == reference(t, k));
    }
  }
}
