// writeJsonNumber (devs/json_number.hpp): std::to_chars' shortest text, "null" for a value JSON
// cannot hold, the end returned exactly, repeated numbers (kept texts) the same as new ones.
#include "devs/json_number.hpp"

#include <bit>
#include <catch2/catch.hpp>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "support/split_mix.hpp"

using namespace yardsim::devs;

namespace {
// (value) => std::to_chars' shortest text, "null" when not finite: the reference
std::string reference(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[64];
  return {buf, std::to_chars(buf, buf + sizeof buf, v).ptr};
}

// (a writer, value) => its text, from a buffer of exactly kJsonNumberSize chars followed by a
// guard that must stay untouched (reported when not)
std::string guarded(char* (*write)(char*, double), double v) {
  char buf[kJsonNumberSize + 8];
  std::memset(buf, '#', sizeof buf);
  char* end = write(buf, v);
  for (std::size_t i = kJsonNumberSize; i < sizeof buf; ++i)
    if (buf[i] != '#') FAIL("written past the buffer for " << v);
  return {buf, end};
}

// (value) => writeJsonNumber's text
std::string written(double v) {
  return guarded(writeJsonNumber, v);
}
}  // namespace

TEST_CASE("writeJsonNumber writes the shortest text and ends where the text ends") {
  // a long text then short ones that repeat (a kept text is copied whole: its end must still be
  // its own length), zeros' signs, values JSON has no number for
  const std::vector<double> values = {-2.2250738585072014e-308,
                                      0.002,
                                      0.002,
                                      -2.2250738585072014e-308,
                                      7.0,
                                      0.0,
                                      -0.0,
                                      0.0,
                                      1999.9999999999998,
                                      2000.0,
                                      1999.9999999999998,
                                      1e21,
                                      123456789012345.0,
                                      5e-324,
                                      std::numeric_limits<double>::infinity(),
                                      -std::numeric_limits<double>::infinity(),
                                      std::numeric_limits<double>::quiet_NaN(),
                                      7.0,
                                      0.002};
  for (int round = 0; round < 3; ++round)
    for (double v : values) CHECK(written(v) == reference(v));
}

TEST_CASE("writeJsonNumber on random doubles, new and repeated, is std::to_chars") {
  yardsim::test::SplitMix64 rng{29};
  std::vector<double> recent;
  for (int i = 0; i < 20000; ++i) {
    // (every third value) => one of the last six again; otherwise random bits
    double v;
    if (i % 3 == 2 && !recent.empty()) {
      v = recent[rng() % recent.size()];
    } else {
      v = std::bit_cast<double>(rng());
      recent.push_back(v);
      if (recent.size() > 6) recent.erase(recent.begin());
    }
    const std::string a = written(v), b = reference(v);
    if (a != b) FAIL(std::hexfloat << v << ": " << a << " against " << b);
  }
}

TEST_CASE("writeJsonMicroseconds is the product's shortest text, the seconds' text kept or not") {
  // (times on grids of every step from 1 us to 1 s, both signs, step counts up to 10^9, random
  // bits, the 1e15 us and 2^53 ends and their neighbours) => each written as a trace does: the
  // seconds' own text first (its digits kept) or not, then the microseconds; every text is
  // std::to_chars' of seconds * 1e6 (the double product), whether the product is the seconds'
  // digits six places on or one of their neighbours
  yardsim::test::SplitMix64 rng{53};
  const double steps[] = {1e-6,   2e-6, 1e-5, 1e-4, 5e-4, 0.001, 0.002,
                          0.0025, 0.01, 0.05, 0.1,  0.25, 1.0};
  std::vector<double> times;
  for (double h : steps)
    for (int i = 0; i < 400; ++i) {
      const auto k = static_cast<double>(rng() % (i < 200 ? 20000 : 1000000000));
      times.push_back(k * h);
      times.push_back(-k * h);
    }
  for (int i = 0; i < 5000; ++i) times.push_back(std::bit_cast<double>(rng()));
  for (double edge : {1e9, 1e9 - 1e-6, 9007199254.740992, 9007199254.740991, 0.0, -0.0, 5e-324,
                      std::numeric_limits<double>::max(), std::numeric_limits<double>::infinity(),
                      std::numeric_limits<double>::quiet_NaN()})
    for (double t = edge, n = 0; n < 4; ++n, t = std::nextafter(t, 0.0)) times.push_back(t);
  std::size_t whole = 0;  // positive products that are whole numbers of microseconds
  for (std::size_t i = 0; i < times.size(); ++i) {
    const double s = times[i];
    if (i % 4 != 3) written(s);  // (three in four) => the seconds' text written first, kept
    const std::string a = guarded(writeJsonMicroseconds, s), b = reference(s * 1e6);
    if (a != b) FAIL(std::hexfloat << s << ": " << a << " against " << b);
    if (s > 0.0 && b.find_first_of(".e") == std::string::npos) ++whole;
  }
  CHECK(whole > 1000);
}
