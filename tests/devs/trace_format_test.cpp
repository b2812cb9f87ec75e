#include "devs/trace_format.hpp"

#include <catch2/catch.hpp>
#include <limits>
#include <yaml-cpp/yaml.h>

using namespace yardsim::devs;

namespace {
struct Opaque {};
struct Printable {
  int a;
};
std::ostream& operator<<(std::ostream& os, const Printable& p) { return os << "a=" << p.a; }

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
