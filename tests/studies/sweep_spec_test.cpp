// Sweep files: the three modes expanded, and mistakes refused at the door with file:line:col.
#include <catch2/catch.hpp>
#include <set>

#include "studies/sweep_spec.hpp"
#include "support/scene_files.hpp"

using namespace yardsim::studies;

namespace {
const std::string kScene =
    "schema_version: 1\nname: s\nparams: {speed: 1.0, mass: 2.0}\ncomponents: {}\n";

// (sweep text) => the spec read from a folder holding it and the scene, and its diagnostics text
std::pair<SweepSpec, std::string> readText(const yardsim::testing::SceneDir& dir,
                                           const std::string& text) {
  dir.write("scene.yaml", kScene);
  yardsim::models::Diagnostics d;
  SweepSpec s = readSweepSpec(dir.write("sweep.yaml", text), d);
  return {s, d.report()};
}
}  // namespace

TEST_CASE("A grid sweep is the product of its lists and ranges, the last parameter fastest") {
  yardsim::testing::SceneDir dir;
  const auto [s, diags] = readText(dir,
                                   "sweep:\n  scene: scene.yaml\n  vary:\n    speed: [4, 6, 8]\n"
                                   "    mass: {from: 0.5, to: 1.5, step: 0.5}\n"
                                   "  collect: [max(a*.tension), min(gap.distance)]\n");
  INFO(diags);
  REQUIRE(diags.empty());
  CHECK(s.mode == "grid");
  CHECK(s.params[0].integer);
  CHECK_FALSE(s.params[1].integer);
  const auto cases = expandCases(s);
  REQUIRE(cases.size() == 9);
  CHECK(cases[0].values == std::vector<double>{4, 0.5});
  CHECK(cases[1].values == std::vector<double>{4, 1.0});
  CHECK(cases[3].values == std::vector<double>{6, 0.5});
  CHECK(cases[8].values == std::vector<double>{8, 1.5});
  CHECK(cases[8].id == 8);
  REQUIRE(s.collect.size() == 2);
  CHECK(s.collect[0].op == "max");
  CHECK(s.collect[0].glob == "a*.tension");
  CHECK(s.operability == std::vector<std::string>{"speed", "mass"});
}

TEST_CASE("Seeds by count go to the scene seed and list mode pairs the i-th values") {
  yardsim::testing::SceneDir dir;
  const auto [s, diags] =
      readText(dir,
               "sweep:\n  scene: scene.yaml\n  mode: list\n  vary:\n    speed: [1, 2, 3]\n"
               "    seed: {count: 3}\n  limits: {max(x.tension): 5.0e6, min(gap.d): {min: 0.5}}\n");
  INFO(diags);
  REQUIRE(diags.empty());
  CHECK(s.params[1].sceneSeed);
  CHECK(s.params[1].values == std::vector<double>{1, 2, 3});
  const auto cases = expandCases(s);
  REQUIRE(cases.size() == 3);
  CHECK(cases[2].values == std::vector<double>{3, 3});
  REQUIRE(s.limits.size() == 2);
  CHECK(s.limits[0].upper);
  CHECK(s.limits[0].bound == 5.0e6);
  CHECK_FALSE(s.limits[1].upper);
  CHECK(s.collect.size() == 2);  // a limit collects its own quantity
}

TEST_CASE("A latin hypercube puts one case in every stratum of every parameter") {
  yardsim::testing::SceneDir dir;
  const auto [s, diags] =
      readText(dir,
               "sweep:\n  scene: scene.yaml\n  mode: latin_hypercube\n  samples: 20\n"
               "  seed: 7\n  vary:\n    speed: {from: 0, to: 10, count: 2}\n"
               "    mass: {from: 1, to: 3, step: 1}\n");
  INFO(diags);
  REQUIRE(diags.empty());
  const auto cases = expandCases(s);
  REQUIRE(cases.size() == 20);
  std::set<int> strataSpeed, strataMass;
  for (const auto& c : cases) {
    strataSpeed.insert(static_cast<int>(c.values[0] / 10.0 * 20.0));
    strataMass.insert(static_cast<int>((c.values[1] - 1.0) / 2.0 * 20.0));
  }
  CHECK(strataSpeed.size() == 20);
  CHECK(strataMass.size() == 20);
  CHECK(expandCases(s)[5].values == cases[5].values);  // deterministic in the sampling seed
}

TEST_CASE("Mistakes in a sweep file are reported with file, line and column") {
  yardsim::testing::SceneDir dir;
  const auto [s, diags] = readText(dir,
                                   "sweep:\n  scene: scene.yaml\n  vary:\n    sped: [1, 2]\n"
                                   "    mass: {from: 1, to: 0, step: 1}\n  mode: gird\n"
                                   "  collect: [peak(x.tension)]\n  case_timeout: -1\n");
  const std::string f = (dir.path() / "sweep.yaml").string();
  CHECK_THAT(diags, Catch::Contains(f + ":4:11: error: sweep.vary.sped: no root parameter 'sped'"));
  CHECK_THAT(diags, Catch::Contains("did you mean 'speed'?"));
  CHECK_THAT(diags, Catch::Contains(f + ":5:34: error: sweep.vary.mass.step"));
  CHECK_THAT(diags, Catch::Contains(
                        f + ":6:9: error: sweep.mode: expected grid, latin_hypercube or list"));
  CHECK_THAT(diags, Catch::Contains(f + ":7:13: error: sweep.collect[0]"));
  CHECK_THAT(diags, Catch::Contains(f + ":8:17: error: sweep.case_timeout"));
}

TEST_CASE("Values are written as scene parameters, whole numbers without a fraction") {
  CHECK(formatValue(3.0, true) == "3");
  CHECK(formatValue(0.1, false) == "0.1");
  CHECK(formatValue(1.0 / 3.0, false) == "0.3333333333333333");
}
