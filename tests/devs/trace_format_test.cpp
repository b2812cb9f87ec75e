#include "devs/trace_format.hpp"

#include <yaml-cpp/yaml.h>
#include <catch2/catch.hpp>
#include <charconv>
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
