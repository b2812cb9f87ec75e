// run.json: a scene with a sea gives each of its multibody models the still-water level (the
// report's water surface); a scene without one gives none.
#include "run/run_summary.hpp"

#include <yaml-cpp/yaml.h>
#include <catch2/catch.hpp>

#include "scene/assembler.hpp"
#include "scene/scene_loader.hpp"

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
