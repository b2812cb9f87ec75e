#include "devs/trace_format.hpp"

#include <yaml-cpp/yaml.h>
#include <bit>
#include <catch2/catch.hpp>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <vector>

using namespace yardsim::devs;

namespace {
struct Opaque {};
struct Printable {
  int a;
};
std::ostream& operator<<(std::ostream& os, const Printable& p) {
  return os << "a=" << p.a;
}

template <class T>
std::string json(const T& v) {
  std::string out;
  TraceFormat<T>::write(out, v);
  return out;
}
}  // namespace

TEST_CASE("values become JSON that parses back to the same value") {
  CHECK(YAML::Load(json(0.1)).as<double>() == 0.1);  // shortest round-trip form
  CHECK(YAML::Load(json(-12345678901234.5)).as<double>() == -12345678901234.5);
  CHECK(json(true) == "true");
  CHECK(json(std::numeric_limits<double>::quiet_NaN()) == "null");
  CHECK(json(std::numeric_limits<double>::infinity()) == "null");
  const std::string tricky = "quote \" backslash \\ newline \n tab \t bell \a";
  CHECK(YAML::Load(json(tricky)).as<std::string>() == tricky);
  CHECK(json(Printable{7}) == "\"a=7\"");
  CHECK(json(Opaque{}) == "null");
}

namespace {
// (value) => its shortest round-trip text straight from std::to_chars: the reference
std::string shortest(double v) {
  char buf[32];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, end);
}
}  // namespace

TEST_CASE("numbers repeated or interleaved are written as std::to_chars writes them") {
  // more distinct values than the writer keeps, repeated, interleaved, and the zeros' signs
  const std::vector<double> values = {0.084,
                                      0.084,
                                      2000.0,
                                      84000.0,
                                      0.084,
                                      -0.0,
                                      0.0,
                                      -0.0,
                                      1.0 / 3.0,
                                      0.1 + 0.2,
                                      0.3,
                                      1e-300,
                                      5e-324,
                                      1.7e308,
                                      0.084,
                                      2000.0,
                                      2000.0000000000002,
                                      -0.0,
                                      0.3,
                                      0.1 + 0.2};
  std::string out, expected;
  for (int round = 0; round < 3; ++round)
    for (double v : values) {
      appendJsonNumber(out, v);
      expected += shortest(v);
      out += ',';
      expected += ',';
    }
  CHECK(out == expected);
  std::string z;
  appendJsonNumber(z, 0.0);
  appendJsonNumber(z, -0.0);
  CHECK(z == "0-0");
}

TEST_CASE("strings with escapes at the ends and in runs are escaped character by character") {
  // (text) => the escaped form built one character at a time: the reference
  auto reference = [](std::string_view text) {
    std::string r = "\"";
    for (char c : text) {
      if (c == '"')
        r += "\\\"";
      else if (c == '\\')
        r += "\\\\";
      else if (c == '\n')
        r += "\\n";
      else if (c == '\r')
        r += "\\r";
      else if (c == '\t')
        r += "\\t";
      else if (static_cast<unsigned char>(c) < 0x20) {
        char buf[8];
        std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(c));
        r += buf;
      } else
        r += c;
    }
    return r + "\"";
  };
  for (std::string_view text :
       {std::string_view(""), std::string_view("plain"), std::string_view("\"q\""),
        std::string_view("\\\\a\\"), std::string_view("\x01start"), std::string_view("end\x1f"),
        std::string_view("a\rb\tc\nd\x02\x03"
                         "e\xc3\xa9"
                         "f")}) {
    std::string out;
    appendJsonString(out, text);
    CHECK(out == reference(text));
  }
}

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
  std::uint64_t s = 0x9e3779b97f4a7c15ULL;
  auto next = [&s] {  // splitmix64
    std::uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  };
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
  for (double v :
       {0.0, -0.0, 1e-5, 9.99999e-5, 9.999995e-5, 999999.0, 999999.5, 1e6, 123456.5, 5e-324,
        2.2250738585072014e-308, 1.7976931348623157e308, std::numeric_limits<double>::infinity(),
        -std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()})
    bad += !check(v);
  CHECK(bad == 0);
}
