// A crane's hook-load curve from the yard database checked during a run: a 1 t load hangs from a
// trolley on two parts (hook load m g); the curve falls from 2 m g at 0 m to 0.5 m g at 10 m, so
// the load is over the curve beyond 6.667 m. The trolley starts at 6 m and runs to 9 m at 0.5 m/s
// from t = 1 s: one over_hook_load alarm when it passes 6.667 m (t about 2.33 s), its value the
// hook load; standing still at 6 m, or with a stronger crane, there is none.
#include "run/hook_load_monitor.hpp"

#include <catch2/catch.hpp>

#include "run/runner.hpp"
#include "scene/assembler.hpp"
#include "scene/scene_loader.hpp"
#include "support/scene_files.hpp"
#include "yard/catalogue.hpp"

using namespace yardsim;

namespace {

constexpr double kWeight = 1000.0 * 9.81;  // N

const char* kCrane = R"(schema_version: 1
mechanics:
  bodies:
    gantry: {parent: world, joint: {name: travel, type: prismatic, axis: [1, 0, 0], hold: true},
             mass: 1.0e5, inertia: [1.0e6, 1.0e6, 1.0e6]}
    trolley: {parent: gantry, joint: {name: trolley_travel, type: prismatic, axis: [0, 1, 0], q0: 6, hold: true},
              placement: {xyz: [0, 0, 20]}, mass: 1.0e4, inertia: [1.0e4, 1.0e4, 1.0e4]}
  ropes:
    hoist: {path: [{body: trolley, point: [0, 0, 0]}, {body: load, point: [0, 0, 0.5]}],
            EA: 1.0e8, L0: 9.5, damping: 1.0e4, parts: 2}
)";

// (folder, the curve's capacity at 0 m and at 10 m, whether the trolley moves) => the run's alarms
std::vector<run::Alarm> craneRun(const testing::SceneDir& dir, double at0, double at10,
                                 bool moves) {
  std::filesystem::remove(dir.path() / "yard.sqlite");
  {
    const yard::Database db = yard::Database::create(dir.file("yard.sqlite"));
    yard::Facility f;
    f.name = "C";
    f.modelFile = "crane.yaml";
    f.capacity = at0;
    f.hookLoadCurve = {{0.0, at0}, {10.0, at10}};
    yard::insertFacility(db, f);
  }
  dir.write("crane.yaml", kCrane);
  std::string text = R"(schema_version: 1
database: yard.sqlite
components:
  crane: {facility: C}
)";
  if (moves)
    text +=
        "  go: {type: joint_actor, params: {joint: crane.trolley_travel, target: 9, speed: 0.5, "
        "start_at: 1}}\n";
  text += R"(mechanics:
  equilibrium: true
  drive_bandwidth: 5.0
  bodies:
    load: {parent: world, joint: {type: free, q0: {xyz: [0, 6, 10]}}, mass: 1000, inertia: [100, 100, 100]}
until: 8
integrator: {method: rk4, dt: 0.002}
)";
  auto scene = scene::loadSceneOrThrow(dir.write("scene.yaml", text));
  REQUIRE(scene->hookLoads.size() == 1);
  CHECK(scene->hookLoads[0].root == "crane.gantry");
  CHECK(scene->hookLoads[0].hoists == std::vector<std::string>{"crane.trolley"});
  auto root = scene::assemble(*scene);
  run::RunOptions opt{dir.path() / "out", scene->until, {}, {}, 0.1, 2000};
  return run::runScene(*scene, *root, opt).alarms;
}

}  // namespace

TEST_CASE("the capacity is linear between the curve's points and 0 beyond it") {
  const std::vector<std::pair<double, double>> curve{{2, 100}, {10, 60}, {20, 60}};
  CHECK(run::hookLoadCapacity(curve, 0) == 100);  // below the first point: its capacity
  CHECK(run::hookLoadCapacity(curve, 2) == 100);
  CHECK(run::hookLoadCapacity(curve, 6) == Approx(80));
  CHECK(run::hookLoadCapacity(curve, 15) == 60);
  CHECK(run::hookLoadCapacity(curve, 20) == 60);
  CHECK(run::hookLoadCapacity(curve, 20.001) == 0);  // not rated beyond
  CHECK(run::hookLoadCapacity({}, 1) == 0);
}

TEST_CASE("a trolley running out past the curve raises one over_hook_load alarm") {
  testing::SceneDir dir;
  const auto alarms = craneRun(dir, 2 * kWeight, 0.5 * kWeight, true);
  INFO(alarms.size());
  REQUIRE(alarms.size() == 1);
  const run::Alarm& a = alarms[0];
  CHECK(a.kind == "over_hook_load");
  CHECK(a.severity == "alarm");
  CHECK(a.element == "crane");
  CHECK(a.model == "mechanics");
  CHECK(a.count == 1);  // it stays over the curve once past 6.667 m
  // (outreach 6 + 0.5 (t - 1) reaches 20/3 m) => t = 2.33 s, later by the servo's lag (1/5 s)
  CHECK(a.first > 2.3);
  CHECK(a.first < 2.6);
  CHECK(a.worst == Approx(kWeight).epsilon(0.05));  // the hook load: m g, and the swing
}

TEST_CASE("no hook-load alarm standing within the curve or with a stronger crane") {
  testing::SceneDir dir;
  CHECK(craneRun(dir, 2 * kWeight, 0.5 * kWeight, false).empty());
  CHECK(craneRun(dir, 2 * kWeight, 1.5 * kWeight, true).empty());
}
