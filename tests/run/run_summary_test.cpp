// run.json: a scene with a sea gives each of its multibody models the still-water level (the
// report's water surface); a scene without one gives none.
#include "run/run_summary.hpp"

#include <yaml-cpp/yaml.h>
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

#include "scene/assembler.hpp"
#include "scene/scene_loader.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;

namespace {
YAML::Node summaryOf(const std::string& file) {
  auto scene = scene::loadSceneOrThrow(file);
  auto root = scene::assemble(*scene);
  return YAML::Load(run::runSummaryJson(*scene, *root, run::RunFacts{}));
}
}  // namespace

TEST_CASE("run.json gives the water level of a floating scene and none for a crane on land") {
  const YAML::Node barge =
      summaryOf(std::string(YARDSIM_SOURCE_DIR) + "/examples/floating_barge/scene.yaml");
  REQUIRE(barge["systems"].size() == 1);
  REQUIRE(barge["systems"][0]["water_level"]);
  CHECK(barge["systems"][0]["water_level"].as<double>() == 0.0);  // the scene's water.level
  const YAML::Node pendulum =
      summaryOf(std::string(YARDSIM_SOURCE_DIR) + "/examples/double_pendulum/scene.yaml");
  REQUIRE(pendulum["systems"].size() == 1);
  CHECK_FALSE(pendulum["systems"][0]["water_level"]);
}

TEST_CASE("run.json gives each system's stiffest mode unless the scene says stiffness_check: off") {
  const std::string stiff =
      std::string(YARDSIM_SOURCE_DIR) + "/examples/stiff/hook_hoist_920t.yaml";
  const YAML::Node on = summaryOf(stiff);
  REQUIRE(on["systems"].size() == 1);
  REQUIRE(on["systems"][0]["omega_max"]);
  // the 16-part hoist over slings: omega_max about 119 rad/s (tests/examples/stiff_test.cpp's
  // hand estimate), the figure the guard judged dt by
  CHECK(on["systems"][0]["omega_max"].as<double>() == Approx(119.0).epsilon(0.05));
  // (the same scene with the guard off) => no estimate: a dense eigenproblem the user silenced
  std::ifstream in(stiff);
  std::stringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  const auto at = s.find("stiffness_check: refuse");
  REQUIRE(at != std::string::npos);
  s.replace(at, std::string("stiffness_check: refuse").size(), "stiffness_check: off");
  testing::SceneDir dir;  // the scene includes nothing, so a copy elsewhere reads the same
  const YAML::Node off = summaryOf(dir.write("off.yaml", s).string());
  REQUIRE(off["systems"].size() == 1);
  CHECK(off["systems"][0]["dt"]);
  CHECK_FALSE(off["systems"][0]["omega_max"]);
}
