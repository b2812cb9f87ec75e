#include "output/loglog_page.hpp"

#include <catch2/catch.hpp>
#include <cstring>

#include <yaml-cpp/yaml.h>

#include "output/html_page.hpp"

using namespace yardsim;

TEST_CASE("a log-log page carries its curves as float32 and its title escaped") {
  output::LogLogPage page{"wp <b>", {{"scene", "s"}}, {{"err", "t [s]", "E [m]", {{"rk4", {1e-3, 2e-3}, {1e-8, 1.6e-7}}}}}, {}};
  const YAML::Node d = YAML::Load(output::logLogJson(page));
  CHECK(d["kind"].as<std::string>() == "loglog");
  CHECK(d["plots"][0]["curves"][0]["label"].as<std::string>() == "rk4");
  // xs 1e-3f, 2e-3f as little-endian float32 in base64 (Python: base64.b64encode(struct.pack("<2f", 1e-3, 2e-3)))
  float f[2] = {1e-3f, 2e-3f};
  unsigned char b[8];
  std::memcpy(b, f, 8);
  CHECK(b[0] == 0x6f);  // the float32 bit pattern of 1e-3 is 0x3a83126f
  CHECK(d["plots"][0]["curves"][0]["xs"].as<std::string>() == "bxKDOm8SAzs=");
  const std::string html = output::htmlPage(page.title, output::logLogJson(page));
  CHECK(html.find("<title>wp &lt;b></title>") != std::string::npos);
}

TEST_CASE("a curve with as many x as y values is required") {
  output::LogLogPage page{"t", {}, {{"p", "x", "y", {{"c", {1, 2}, {1}}}}}, {}};
  CHECK_THROWS_WITH(output::logLogJson(page), Catch::Contains("'c' has 2 x and 1 y values"));
}
