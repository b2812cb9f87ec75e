// Blow-up diagnosis of the multibody model: an unstable step stops the run at once through the
// energy balance (long before NaN), naming the time, the body, the rope and the cause the
// stiffness guard predicts; a stable step runs through; an opening loop is named.
#include <catch2/catch.hpp>
#include <fstream>
#include <sstream>

#include "scene/mechanics_reader.hpp"
#include "mechanics/build.hpp"
#include "devs/coupled.hpp"
#include "devs/simulator.hpp"
#include "scene/assembler.hpp"
#include "models/multibody/multibody_model.hpp"
#include "models/numerical_error.hpp"
#include "run/runner.hpp"
#include "scene/scene_loader.hpp"
#include "support/csv_file.hpp"
#include "support/scene_files.hpp"
#include "support/test_paths.hpp"

using namespace yardsim;

namespace {
std::string hookScene(const std::string& integrator) {
  std::ifstream in(std::string(YARDSIM_SOURCE_DIR) + "/examples/stiff/hook_hoist_920t.yaml");
  std::stringstream s;
  s << in.rdbuf();
  std::string text = s.str();
  const std::string from = "integrator: {method: rk4, dt: 0.0125, stiffness_check: refuse}";
  REQUIRE(text.find(from) != std::string::npos);
  return text.replace(text.find(from), from.size(), integrator);
}
}  // namespace

TEST_CASE("RK4 beyond its limit on the hook scene stops at once, naming hook, hoist, time and the guard's step") {
  testing::SceneDir dir;
  auto scene = scene::loadSceneOrThrow(dir.write("s.yaml", hookScene("integrator: {method: rk4, dt: 0.05, stiffness_check: off}")));
  auto root = scene::assemble(*scene);
  std::string what;
  try {
    run::runScene(*scene, *root, {dir.path() / "out", scene->until, {}, {}, 0.1});
  } catch (const models::NumericalError& e) {
    what = e.what();
  }
  INFO(what);
  CHECK_THAT(what, Catch::Contains("body 'hook'") && Catch::Contains("energy balance rose") &&
                       Catch::Contains("rope 'hoist'") && Catch::Contains("dt <= 0.021"));
  // caught within a few steps (the amplification is ~46 per step), long before a NaN
  CHECK_THAT(what, Catch::Contains("t = 0.05") || Catch::Contains("t = 0.1") || Catch::Contains("t = 0.15"));
  const testing::CsvFile csv((dir.path() / "out" / "timeseries.csv").string());
  CHECK(csv.rows.size() >= 1);  // what was recorded is on disk
}

TEST_CASE("RK4 inside its limit on the hook scene runs through with a bounded energy balance") {
  testing::SceneDir dir;
  auto scene = scene::loadSceneOrThrow(dir.write("s.yaml", hookScene("integrator: {method: rk4, dt: 0.0125}")));
  auto root = scene::assemble(*scene);
  const auto r = run::runScene(*scene, *root, {dir.path() / "out", scene->until, {}, {}, 0.1});
  CHECK(r.tEnd == Approx(5.0));
  const testing::CsvFile csv((dir.path() / "out" / "timeseries.csv").string());
  const int bal = csv.column("mechanics.energy_balance[J]");
  REQUIRE(bal > 0);
  double drift = 0;
  for (const auto& row : csv.rows) drift = std::max(drift, std::abs(row[bal] - csv.rows[0][bal]));
  // the hook's mode (2 cm at 119 rad/s against 8e7 + 2e8 N/m: ~6e4 J) is damped by RK4 at
  // omega dt = 1.49; the energy can only go down
  CHECK(drift < 1e5);
}

TEST_CASE("a loop that opens beyond its bound stops the run naming the loop") {
  // the Ku et al. slider-crank without projection, with a bound far below its drift
  const YAML::Node p = YAML::LoadFile(std::string(YARDSIM_SOURCE_DIR) + "/examples/ku2014_loop/scene.yaml");
  const YAML::Node mp = p["components"]["mechanism"]["params"];
  models::Params params;
  for (const char* key : {"bodies", "loops"}) params.set(key, mp[key], {});
  for (const char* key : {"ropes", "equalizers"}) params.set(key, YAML::Load("{}"), {});
  params.set("gravity", YAML::Load("[0, 0, -9.81]"), {});
  auto mech = mechanics::buildMechanics(scene::parseMechanics(
      params, [](const std::string& k, const YAML::Node&, const std::string& sub, const std::string& m) {
        FAIL(k + "." + sub + ": " + m);
      }));
  models::MultibodyOptions opt;
  opt.dt = 0.01;
  opt.projectLoops = false;
  opt.loopResidualLimit = 1e-9;
  devs::Coupled root("root");
  root.add<models::MultibodyModel>("mechanism", std::move(mech), opt);
  std::string what;
  try {
    devs::Simulator sim(root);
    sim.runUntil(2.0);
  } catch (const models::NumericalError& e) {
    what = e.what();
  }
  INFO(what);
  CHECK_THAT(what, Catch::Contains("loop 'cylindrical1' opened") && Catch::Contains("project_loops: true"));
}
