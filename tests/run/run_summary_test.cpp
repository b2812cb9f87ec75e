// run.json: a scene with a sea gives each of its multibody models the still-water level (the
// report's water surface); a scene without one gives none. A marched free surface (rankine_td)
// gives its panel step and emp limit (systems[].marching), what the stiffness guard judged.
#include "run/run_summary.hpp"

#include <yaml-cpp/yaml.h>
#include <catch2/catch.hpp>

#include <filesystem>

#include "forces/geometry/mesh_io.hpp"
#include "forces/geometry/primitive_meshes.hpp"
#include "scene/assembler.hpp"
#include "scene/scene_loader.hpp"
#include "support/scene_files.hpp"
#include "support/test_paths.hpp"

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

TEST_CASE("run.json gives a marched free surface's panel step beside its emp limit and omega_max") {
  // (the box barge of tests/scene/floating_reader_hydrodynamics_test.cpp marched by rankine_td,
  // panel step 0.1 s at RK4 0.05 s) => systems[0].marching: the entry, its step and the limit the
  // stiffness guard judged it against (g lambda_max limit^2 = 4)
  testing::SceneDir dir;
  std::filesystem::create_directories(dir.path() / "meshes");
  forces::writeStl(forces::boxMesh(dynamics::Vector3(20, 8, 4), 2, 2, 1), dir.file("meshes/barge.stl"));
  const auto file = dir.write("s.yaml", R"(schema_version: 1
integrator: {method: rk4, dt: 0.05}
mechanics:
  water: {density: 1025}
  bodies:
    barge: {parent: world, joint: {type: free, q0: {xyz: [0, 0, 0.5]}}, mass: 246000, inertia: [1.64e6, 8.53e6, 9.51e6]}
  hydrostatics:
    hull: {body: barge, mesh: meshes/barge.stl}
  hydrodynamics:
    hd: {body: barge, method: rankine_td, hull: meshes/barge.stl, dt: 0.05,
         settings: {truncation_radius: 60, first_spacing: 1.5, max_spacing: 4, longest_period: 4, panel_step: 0.1}}
)");
  const YAML::Node summary = summaryOf(file.string());
  REQUIRE(summary["systems"].size() == 1);
  const YAML::Node system = summary["systems"][0];
  CHECK(system["omega_max"].as<double>() > 0.0);
  REQUIRE(system["marching"].size() == 1);
  const YAML::Node m = system["marching"][0];
  CHECK(m["name"].as<std::string>() == "hd");
  CHECK(m["scheme"].as<std::string>() == "emp");
  CHECK(m["step"].as<double>() == 0.1);
  const double limit = m["limit"].as<double>(), lambda = m["lambda_max"].as<double>();
  CHECK(9.81 * lambda * limit * limit == Approx(4.0).epsilon(1e-9));
  CHECK(limit > 0.1);
  // (a scene without a marched provider) => no `marching` key
  const YAML::Node barge = summaryOf(std::string(YARDSIM_SOURCE_DIR) + "/examples/floating_barge/scene.yaml");
  CHECK_FALSE(barge["systems"][0]["marching"]);
}
