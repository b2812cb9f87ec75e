// The `springs:`, `joint_springs:` and `bushings:` keys of scene/providers/: read from YAML, run
// in a scene and compared with the closed forms of a single-degree-of-freedom oscillator
// x(t) = x0 e^(-zeta w t) (cos(wd t) + zeta / sqrt(1 - zeta^2) sin(wd t)), w = sqrt(k/m),
// through their channels; problems reported at their YAML nodes with "did you mean".
#include <catch2/catch.hpp>
#include <cmath>

#include "run/runner.hpp"
#include "scene/assembler.hpp"
#include "scene/scene_loader.hpp"
#include "support/csv_file.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;
using Catch::Matchers::Contains;

namespace {

// (scene text, until) => its timeseries.csv after a run
testing::CsvFile simulate(const testing::SceneDir& dir, const std::string& text, double until) {
  auto scene = scene::loadSceneOrThrow(dir.write("s.yaml", text));
  auto root = scene::assemble(*scene);
  run::runScene(*scene, *root, {dir.path() / "out", until, {}, {}, 0.1});
  return testing::CsvFile((dir.path() / "out" / "timeseries.csv").string());
}

// (x0, w, zeta, t) => the damped free oscillation released from rest at x0
double oscillation(double x0, double w, double zeta, double t) {
  const double wd = w * std::sqrt(1 - zeta * zeta);
  return x0 * std::exp(-zeta * w * t) *
         (std::cos(wd * t) + zeta / std::sqrt(1 - zeta * zeta) * std::sin(wd * t));
}

// a 10 kg block on a vertical slider, 1.1 m below a world point, on a spring of free length 1 m
std::string block(const std::string& spring, const std::string& extra = "") {
  return R"(schema_version: 1
integrator: {method: rk4, dt: 0.0005}
mechanics:
  gravity: [0, 0, 0]
  bodies:
    block:
      parent: world
      joint: {type: prismatic, axis: [0, 0, 1], q0: -1.1}
      mass: 10
      inertia: [1, 1, 1]
  springs:
)" + spring +
         extra +
         R"(record: {interval: 0.01, channels: ["block_joint.q", "block_joint.v", "spring.*", "mechanics.energy_balance"]}
)";
}

}  // namespace

TEST_CASE(
    "springs: a block on a spring-damper oscillates at sqrt(k/m) with the closed-form decay") {
  testing::SceneDir dir;
  // (k = 4000 N/m, m = 10 kg: w = 20 rad/s; c = 40 N s/m: zeta = c / (2 sqrt(k m)) = 0.1)
  const auto csv =
      simulate(dir,
               block("    spring: {between: [{point: [0, 0, 0]}, {body: block, point: [0, "
                     "0, 0]}], k: 4000, c: 40, free_length: 1}\n"),
               1.0);
  const int q = csv.column("block_joint.q[m]"), v = csv.column("block_joint.v[m/s]"),
            force = csv.column("spring.force[N]"), length = csv.column("spring.length[m]"),
            power = csv.column("spring.power[W]"),
            balance = csv.column("mechanics.energy_balance[J]");
  REQUIRE(std::min({q, v, force, length, power, balance}) > 0);
  REQUIRE(csv.rows.size() == 101);
  double worst = 0;
  for (const auto& r : csv.rows) {
    const double x = oscillation(0.1, 20.0, 0.1, r[0]);  // stretch beyond the free length
    worst = std::max(worst, std::abs(-r[q] - 1.0 - x));
    CHECK(r[length] == Approx(-r[q]).margin(1e-12));
    // (tension k x + c L', L' = -q'; power -c L'^2) => the channels
    CHECK(r[force] == Approx(4000.0 * (r[length] - 1.0) - 40.0 * r[v]).margin(1e-9));
    CHECK(r[power] == Approx(-40.0 * r[v] * r[v]).margin(1e-9));
    // (the work of the damping, trapezoidal per step) => closed to 5e-6 of k x0^2 / 2 = 20 J
    CHECK(std::abs(r[balance] - csv.rows[0][balance]) < 5e-6 * 20.0);
  }
  CHECK(worst < 1e-8);
  CHECK(csv.rows[0][force] == Approx(400.0).epsilon(1e-12));  // at rest: k x only
}

TEST_CASE("springs: a compressed spring pushes, with preload, table law and stops") {
  testing::SceneDir dir;
  // (table f = 4000 x + 100 through its points, preload -100 N) => f = 4000 x: the block 0.1 m
  // above the free length (compressed) oscillates like the linear spring, pushed back first
  const auto csv =
      simulate(dir,
               block("    spring: {between: [{point: [0, 0, 0]}, {body: block, point: [0, "
                     "0, 0]}], table: [[-1, -3900], [1, 4100]], preload: -100, "
                     "free_length: 1.2, stops: {min_length: 0.1, k: 1.0e6}}\n"),
               0.5);
  const int q = csv.column("block_joint.q[m]"), force = csv.column("spring.force[N]");
  REQUIRE(std::min(q, force) > 0);
  CHECK(csv.rows[0][force] == Approx(-400.0).epsilon(1e-12));  // pushes
  double worst = 0;
  for (const auto& r : csv.rows)
    worst = std::max(worst, std::abs(-r[q] - 1.2 + oscillation(0.1, 20.0, 0.0, r[0])));
  CHECK(worst < 1e-8);
}

TEST_CASE("joint_springs: a rotor on a torsion spring oscillates at sqrt(k/I) about its neutral") {
  testing::SceneDir dir;
  // (k = 50 N m/rad, Izz = 2 kg m^2: w = 5 rad/s; neutral 10 deg, released 0.2 rad from it)
  const auto csv = simulate(dir, R"(schema_version: 1
integrator: {method: rk4, dt: 0.001}
mechanics:
  gravity: [0, 0, 0]
  bodies:
    rotor:
      parent: world
      joint: {name: hinge, type: revolute, axis: [0, 0, 1], q0: 0.37453292519943295}
      mass: 10
      inertia: [1, 1, 2]
  joint_springs:
    torsion: {body: rotor, k: 50, neutral_deg: 10}
record: {interval: 0.02, channels: ["hinge.q", "torsion.*"]}
)",
                            2.0);
  const int q = csv.column("hinge.q[rad]"), force = csv.column("torsion.force[N m]"),
            deflection = csv.column("torsion.deflection[rad]");
  REQUIRE(std::min({q, force, deflection}) > 0);
  const double neutral = 10.0 * M_PI / 180.0;
  double worst = 0;
  for (const auto& r : csv.rows) {
    worst = std::max(worst, std::abs(r[q] - neutral - oscillation(0.2, 5.0, 0.0, r[0])));
    CHECK(r[deflection] == Approx(r[q] - neutral).margin(1e-12));
    CHECK(r[force] == Approx(-50.0 * r[deflection]).margin(1e-9));
  }
  CHECK(worst < 1e-8);
}

TEST_CASE(
    "bushings: a free body on a bushing oscillates in surge and yaw at sqrt(k/m), sqrt(k/I)") {
  testing::SceneDir dir;
  // (kx = 1e4 N/m, m = 100 kg: w = 10; krz = 300 N m/rad, Izz = 30: w = sqrt(10)) => decoupled
  // about the centre of mass, exact in yaw (one axis: the rotation vector is the angle)
  const auto csv = simulate(dir, R"(schema_version: 1
integrator: {method: rk4, dt: 0.001}
mechanics:
  gravity: [0, 0, 0]
  bodies:
    float:
      parent: world
      joint: {type: free, q0: {xyz: [0.05, 0, 0], rpy_deg: [0, 0, 5.729577951308232]}}
      mass: 100
      inertia: [10, 20, 30]
  bushings:
    mount:
      body_b: float
      stiffness: [1.0e4, 2.0e4, 3.0e4, 100, 200, 300]
record: {interval: 0.02, channels: ["float.x", "float.yaw", "mount.*"]}
)",
                            2.0);
  const int x = csv.column("float.x[m]"), yaw = csv.column("float.yaw[rad]"),
            fx = csv.column("mount.fx[N]"), mz = csv.column("mount.mz[N m]");
  REQUIRE(std::min({x, yaw, fx, mz}) > 0);
  double worstX = 0, worstYaw = 0;
  for (const auto& r : csv.rows) {
    worstX = std::max(worstX, std::abs(r[x] - oscillation(0.05, 10.0, 0.0, r[0])));
    worstYaw = std::max(worstYaw, std::abs(r[yaw] - oscillation(0.1, std::sqrt(10.0), 0.0, r[0])));
  }
  CHECK(worstX < 1e-8);
  CHECK(worstYaw < 1e-8);
  CHECK(csv.rows[0][fx] == Approx(1.0e4 * 0.05).epsilon(1e-12));  // Q = K delta, in F
  CHECK(csv.rows[0][mz] == Approx(300 * 0.1).epsilon(1e-9));
}

TEST_CASE("bushings: frames turned by rpy_deg and by a fragment's placement orient the stiffness") {
  testing::SceneDir dir;
  // (the frames turned 90 deg about z in a fragment placed turned another 90 deg) => F's x is
  // the world's -x: the surge stiffness kx = 1e4 N/m acts along world x (w = 10 rad/s); a
  // reader that lost the placement's turn would put ky = 2e4 there (w = 14.1 rad/s)
  dir.write("mount.yaml", R"(schema_version: 1
mechanics:
  bodies:
    float:
      parent: world
      joint: {type: free, q0: {xyz: [0, 0.05, 0]}}
      mass: 100
      inertia: [10, 20, 30]
  bushings:
    mount:
      frame_a: {rpy_deg: [0, 0, 90]}
      body_b: float
      frame_b: {rpy_deg: [0, 0, 90]}
      stiffness: [1.0e4, 2.0e4, 3.0e4, 100, 200, 300]
)");
  const auto turned = simulate(dir, R"(schema_version: 1
integrator: {method: rk4, dt: 0.001}
mechanics:
  gravity: [0, 0, 0]
components:
  rig: {include: mount.yaml, placement: {xyz: [0, 0, 0], rpy_deg: [0, 0, 90]}}
record: {interval: 0.02, channels: ["rig.float.x", "rig.float.y"]}
)",
                               1.0);
  const int x = turned.column("rig.float.x[m]"), y = turned.column("rig.float.y[m]");
  REQUIRE(std::min(x, y) > 0);
  // (the body placed at world (-0.05, 0) by the fragment) => x = -0.05 cos(10 t), y = 0
  double worst = 0;
  for (const auto& r : turned.rows) {
    worst = std::max(worst, std::abs(r[x] - oscillation(-0.05, 10.0, 0.0, r[0])));
    CHECK(std::abs(r[y]) < 1e-9);
  }
  CHECK(worst < 1e-8);
}

TEST_CASE("springs, joint springs and bushings: problems at their nodes, with did you mean") {
  testing::SceneDir dir;
  const auto typo = scene::loadScene(
      dir.write("a.yaml", block("    spring: {between: [{point: [0, 0, 0]}, {body: block}], k: 1, "
                                "free_lenght: 1}\n")));
  CHECK_FALSE(typo.scene);
  CHECK_THAT(typo.diagnostics.report(),
             Contains("a.yaml:12:79:") && Contains("free_lenght") && Contains("free_length"));
  const auto bad = scene::loadScene(dir.write(
      "b.yaml", block("    spring: {between: [{point: [0, 0, 0]}, {body: blok}], k: -1}\n")));
  CHECK_FALSE(bad.scene);
  CHECK_THAT(bad.diagnostics.report(), Contains("b.yaml:12:62:") && Contains("k must be >= 0") &&
                                           Contains("missing required key 'free_length'"));
  const auto body = scene::loadScene(
      dir.write("f.yaml", block("    spring: {between: [{point: [0, 0, 0]}, {body: blok}], k: 1, "
                                "free_length: 1}\n")));
  CHECK_FALSE(body.scene);
  CHECK_THAT(body.diagnostics.report(), Contains("unknown body 'blok'") && Contains("block"));
  const auto table = scene::loadScene(dir.write(
      "c.yaml", block("    spring: {between: [{point: [0, 0, 0]}, {body: block}], k: 1, table: "
                      "[[0, 0], [1, 1]], free_length: 1}\n")));
  CHECK_THAT(table.diagnostics.report(), Contains("either k or table"));
  const auto order = scene::loadScene(
      dir.write("d.yaml", block("    spring: {between: [{point: [0, 0, 0]}, {body: block}], table: "
                                "[[1, 0], [0, 1]], free_length: 1}\n")));
  CHECK_THAT(order.diagnostics.report(), Contains("d.yaml:") && Contains("increasing"));
  const auto joint = scene::loadScene(dir.write(
      "e.yaml", block("    spring: {between: [{point: [0, 0, 0]}, {body: block}], k: "
                      "1, free_length: 1}\n",
                      "  joint_springs:\n    j: {body: world, k: 1, c: -2}\n  "
                      "bushings:\n    b: {body_b: block, stiffnes: [1, 1, 1, 1, 1, 1], "
                      "damping: [[1, 2, 0, 0, 0, 0], [0, 1, 0, 0, 0, 0], [0, 0, 1, 0, 0, "
                      "0], [0, 0, 0, 1, 0, 0], [0, 0, 0, 0, 1, 0], [0, 0, 0, 0, 0, 1]]}\n")));
  CHECK_FALSE(joint.scene);
  CHECK_THAT(joint.diagnostics.report(), Contains("not on the world") && Contains("must be >= 0") &&
                                             Contains("stiffnes") && Contains("stiffness") &&
                                             Contains("must be symmetric"));
}
