// forces/lines/lumped_rope_over_sheave.hpp: how the segments are shared between the spans, and
// the rope's forces against its energy by virtual work: at rest (v = 0, so no damping acts) the
// system's generalized forces M(q) a(q) equal -dE/dq, E the kinetic-free energy of the system
// (gravity and every provider's potential, mechanics::energy) by central differences, at a state
// where every node, the sheave's carrier and the block are moved off their rest. This checks the
// spans, the segment over the sheave and the gravity on p and q replaced by the half segment's
// net weight against one another.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <string>

#include "dynamics/crba.hpp"
#include "forces/lines/lumped_rope_over_sheave.hpp"
#include "mechanics/build.hpp"
#include "mechanics/data.hpp"
#include "mechanics/energy.hpp"
#include "mechanics/set_points.hpp"
#include "mechanics/stage.hpp"
#include "mechanics/system.hpp"
#include "scene/mechanical_systems.hpp"
#include "scene/scene_loader.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;
using dynamics::Vector3;

TEST_CASE("lumped rope over a sheave: segments shared in proportion to the spans") {
  const Vector3 s(0, 0, 30);
  CHECK(forces::firstSpanSegments(21, Vector3(0, 0, 10), s, Vector3(0, 0, 10)) == 10);
  // (10 m : 30 m of path) => 5 and 15 segments, and half the one over the sheave on each side
  CHECK(forces::firstSpanSegments(21, Vector3(0, 0, 20), s, Vector3(0, 0, 0)) == 5);
  CHECK(forces::firstSpanSegments(3, Vector3(0, 0, 29), s, Vector3(0, 0, 0)) == 1);  // at least 1
  CHECK(forces::firstSpanSegments(3, Vector3(0, 0, 0), s, Vector3(0, 0, 29)) == 1);  // each side
  CHECK(forces::sheaveNodeName("hoist", true, 7) == "hoist.a.node7");
  CHECK(forces::sheaveNodeName("hoist", false, 7) == "hoist.b.node0");
}

TEST_CASE("lumped rope over a sheave: its forces are minus the gradient of its energy") {
  // (without bending, and with EI 2e5 N m^2 in both spans: their bending energy and forces, the
  // ends of each span and the sheave segment pinned)
  for (const std::string bending : {"", ", EI: 2.0e5"}) {
    INFO("'" << bending << "'");
    testing::SceneDir dir;
    auto scene = scene::loadSceneOrThrow(dir.write("s.yaml", R"(schema_version: 1
integrator: {method: rk4, dt: 0.001}
mechanics:
  bodies:
    carrier: {parent: world, joint: {name: travel, type: prismatic, axis: [1, 0, 0]}, placement: {xyz: [0, 0, 30]}, mass: 500, inertia: [1, 1, 1]}
    anchor: {parent: world, joint: {type: fixed}, placement: {xyz: [-3, 0, 12]}, mass: 1000, inertia: [1, 1, 1]}
    block: {parent: world, joint: {name: lift, type: prismatic, axis: [0, 0, 1], q0: 12}, placement: {xyz: [4, 0, 0]}, mass: 2000, inertia: [1, 1, 1]}
  ropes:
    hoist: {model: lumped, path: [{body: anchor}, {body: carrier, point: [0, 0, 0.5]}, {body: block}],
            L0: 36, segments: 7, EA: 2.0e6, mass_per_length: 10, diameter: 0.04)" +
                                                                 bending + R"(}
)"));
    REQUIRE(scene->systems.size() == 1);
    const auto mech = std::make_unique<mechanics::BuiltMechanics>(
        mechanics::buildMechanics(scene->systems[0]->spec));
    const mechanics::System system(*mech, {}, "s");
    REQUIRE(system.contributed().size() == 1);
    mechanics::Data data(system);
    const auto& model = mech->model;
    mechanics::SetPoints held{
        std::vector<mechanics::JointDrive>(static_cast<std::size_t>(model.nbodies)),
        std::vector<mechanics::ActorLoad>(static_cast<std::size_t>(model.nbodies)),
        std::vector<mechanics::WinchJob>(system.ropes().size())};
    data.setPoints = &held;
    mechanics::connectStage(system, data);
    // (7 segments over 18 + 20 m: 3 in span A, p, q, 3 in span B; all on translation joints or
    // sliders, so q and v coincide) => a state moved off rest by up to 5 cm
    REQUIRE(model.bodyIndex("hoist.a.node3") > 0);
    REQUIRE(model.bodyIndex("hoist.b.node0") > 0);
    REQUIRE(model.nq == model.nv);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> jitter(-0.05, 0.05);
    Eigen::VectorXd q = mech->q0;
    for (Eigen::Index k = 0; k < q.size(); ++k) q[k] += jitter(rng);
    const Eigen::VectorXd v = Eigen::VectorXd::Zero(model.nv);
    Eigen::VectorXd a(model.nv);
    data.kernel.acceleration(0.0, q, v, a);
    dynamics::Data kin(model);
    const Eigen::VectorXd force = dynamics::crba(model, kin, q) * a;
    auto energy = [&](const Eigen::VectorXd& x) {
      return mechanics::energy(system, data, kin, x, v, 0.0);
    };
    const double h = 1e-5;
    double largest = 0.0;
    for (Eigen::Index k = 0; k < q.size(); ++k) largest = std::max(largest, std::abs(force[k]));
    for (Eigen::Index k = 0; k < q.size(); ++k) {
      Eigen::VectorXd up = q, down = q;
      up[k] += h;
      down[k] -= h;
      const double gradient = (energy(up) - energy(down)) / (2.0 * h);
      INFO("dof " << k << ": M a " << force[k] << " N, -dE/dq " << -gradient << " N");
      CHECK(force[k] == Approx(-gradient).margin(1e-6 * largest));
    }
    CHECK(largest > 1e3);
  }
}
