// The stiffness estimate against closed forms: a two-mass chain of ropes (the hook between the
// hoist and the slings), the 1 kg shackle under a 1000 t block, a slack rope (estimated taut),
// and a pendulum without any rope (sqrt(g/l)).
#include <catch2/catch.hpp>
#include <cmath>

#include "forces/geometry/mesh_io.hpp"
#include "forces/geometry/primitive_meshes.hpp"
#include "mechanics/build.hpp"
#include "scene/mechanical_systems.hpp"
#include "mechanics/step_verdict.hpp"
#include "mechanics/stiffness_estimate.hpp"
#include "scene/scene_loader.hpp"
#include "support/scene_files.hpp"
#include "support/test_paths.hpp"

using namespace yardsim;

namespace {
mechanics::StiffnessEstimate estimateOf(const std::string& file) {
  auto scene = scene::loadSceneOrThrow(file);
  REQUIRE(scene->systems.size() == 1);
  return mechanics::estimateStiffness(mechanics::buildMechanics(scene->systems[0]->spec));
}
std::string example(const std::string& name) {
  return std::string(YARDSIM_SOURCE_DIR) + "/examples/stiff/" + name + ".yaml";
}
// (masses m1 (between springs k1 to ground and k2), m2 (on k2)) => the higher frequency
double twoMassHigh(double k1, double k2, double m1, double m2) {
  const double a = (k1 + k2) / m1 + k2 / m2, b = k1 * k2 / (m1 * m2);
  return std::sqrt(0.5 * (a + std::sqrt(a * a - 4 * b)));
}
}  // namespace

TEST_CASE("hook between a 16-part hoist and four slings: the two-mass closed form, named hook and hoist") {
  const auto e = estimateOf(example("hook_hoist_920t"));
  const double expected = twoMassHigh(16 * 2e8 / 40, 4 * 5e8 / 10, 2e4, 9.2e5);
  INFO(mechanics::describe(e));
  CHECK(expected == Approx(119.1).epsilon(0.01));
  CHECK(e.omegaMax == Approx(expected).epsilon(1e-3));
  CHECK(e.dampingRatio == Approx(0.0).margin(1e-6));
  CHECK(e.body == "hook");
  CHECK(e.element == "rope 'hoist'");
}

TEST_CASE("mass ratio 1e6: the 1 kg shackle between the rope and the link") {
  const auto e = estimateOf(example("mass_ratio"));
  CHECK(e.omegaMax == Approx(twoMassHigh(1e8 / 20, 1e8 / 1, 1.0, 1e6)).epsilon(1e-3));
  CHECK(e.body == "shackle");
  CHECK(e.element == "rope 'link'");
}

TEST_CASE("a slack rope is estimated taut: the bounce frequency sqrt(EA/(L m))") {
  // slack_snap: 10 t on EA 2e8 N, the rope 0.5 m slack at the start (L = 19.5 m)
  const auto e = estimateOf(example("slack_snap"));
  CHECK(e.omegaMax == Approx(std::sqrt(2e8 / 19.5 / 1e4)).epsilon(1e-3));
  CHECK(e.element == "rope 'rope'");
}

TEST_CASE("a pendulum without ropes: sqrt(g/l) from the linearised gravity") {
  testing::SceneDir dir;
  const auto file = dir.write("pendulum.yaml", R"(schema_version: 1
integrator: {method: rk4, dt: 0.01}
mechanics:
  bodies:
    bob: {parent: world, joint: {type: revolute, axis: [0, 1, 0], q0: 0.01}, mass: 2.0, com: [0, 0, -4.0], inertia: [1.0e-9, 1.0e-9, 1.0e-9]}
until: 1
)");
  const auto e = estimateOf(file.string());
  CHECK(e.omegaMax == Approx(std::sqrt(9.81 / 4.0)).epsilon(1e-4));
  CHECK(e.body == "bob");
  CHECK(e.element.empty());
}

TEST_CASE("the 3500 t block's lumped hoist: omega_max about 1.4e3 rad/s in the rope nodes") {
  const auto e = estimateOf(example("block_3500t"));
  // chain of 9 nodes of 1920 kg between 9.6e8 N/m segments, ends held by the far heavier hook:
  // 2 sqrt(k/m) sin(9 pi / 20)
  CHECK(e.omegaMax == Approx(2 * std::sqrt(9.6e8 / 1920.0) * std::sin(9 * M_PI / 20)).epsilon(0.01));
  CHECK(e.body.rfind("node", 0) == 0);
  CHECK(e.element.rfind("rope 'hoist", 0) == 0);
}

TEST_CASE("a floating box barge: the estimate sees its hydrostatics, heave at sqrt(rho g A / m), damping ratio c / 2 sqrt(k m)") {
  // 20 x 8 x 4 box of 246 t, centre of mass at mid-depth: draft 1.5 m; heave is its stiffest mode
  // (roll sqrt(m g GM_T / I_xx) = 1.84 rad/s, pitch 2.44 rad/s); the hull's waterplane gives
  // k = rho g L B, the damping c on heave
  testing::SceneDir dir;
  std::filesystem::create_directories(dir.path() / "meshes");
  forces::writeStl(forces::boxMesh(dynamics::Vector3(20, 8, 4), 2, 2, 1), dir.file("meshes/barge.stl"));
  const double m = 246000.0, rho = 1025.0, g = 9.81, k = rho * g * 20 * 8, c = 2e5;
  const std::string yaml = R"(schema_version: 1
integrator: {method: rk4, dt: 0.01}
mechanics:
  gravity: [0, 0, -9.81]
  water: {density: 1025}
  bodies:
    barge:
      parent: world
      joint: {type: free, q0: {xyz: [0, 0, 0.5]}}
      mass: 246000
      inertia: [1.64e6, 8.53e6, 9.51e6]
  hydrostatics:
    hull: {body: barge, mesh: meshes/barge.stl}
  damping:
    heave: {body: barge, linear: [0, 0, 2e5, 0, 0, 0], quadratic: [0, 0, 0, 0, 0, 0]}
)";
  auto scene = scene::loadSceneOrThrow(dir.write("barge.yaml", yaml));
  REQUIRE(scene->systems.size() == 1);
  const auto e = mechanics::estimateStiffness(mechanics::buildMechanics(scene->systems[0]->spec));
  INFO(mechanics::describe(e));
  CHECK(e.omegaMax == Approx(std::sqrt(k / m)).epsilon(1e-4));
  CHECK(e.dampingRatio == Approx(c / (2.0 * std::sqrt(k * m))).epsilon(1e-4));
  CHECK(e.body == "barge");
  CHECK(e.element == "provider 'hull'");
  // (the guard's words, where a user reads the estimate) => the damping ratio with it
  const double zeta = c / (2.0 * std::sqrt(k * m));
  CHECK(zeta == Approx(0.159).epsilon(2e-3));
  CHECK_THAT(mechanics::describe(e), Catch::Contains("omega_max = 2.56 rad/s, damping ratio 0.159"));
  const mechanics::StepVerdict v = mechanics::judgeStep(e, "rk4", 2.0);  // 2.56 x 2 s > 2.83
  CHECK_FALSE(v.stable);
  CHECK_THAT(v.message(), Catch::Contains("damping ratio 0.159"));
}
