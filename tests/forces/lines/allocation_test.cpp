// The lines allocate nothing once built: a catenary line's and a lumped line's forces at a stage,
// and the lumped-line providers of scenes (a buoy's mooring chains, a crane rope from a point and
// over a sheave) with their scratch, their energy and power; every heap allocation counted.
#include <catch2/catch.hpp>

#include "support/allocation_counter.hpp"

#include <vector>

#include "dynamics/kinematics.hpp"
#include "forces/force_rig.hpp"
#include "forces/lines/catenary_line.hpp"
#include "forces/lines/lumped_line.hpp"
#include "forces/lines/lumped_rope_over_sheave.hpp"
#include "forces/provider_outputs.hpp"
#include "tests/mechanics/mechanics_fixture.hpp"

using yardsim::testing::allocationCount;

using namespace yardsim;
using namespace yardsim::forces;
using namespace yardsim::forces::testing;

TEST_CASE("catenary lines do not allocate at a stage") {
  dynamics::ModelBuilder b;
  b.setGravity(Vector3::Zero());
  b.addBody("barge", "world", dynamics::Joint::free(), dynamics::Transform::identity(),
            dynamics::boxInertia(2e6, Vector3(40, 12, 5)));
  const dynamics::Model m = b.build();
  CatenaryLine taut("taut", m, {0, Vector3(-420, 0, -150)}, {1, Vector3(-20, 0, 0)},
                    {500.0, 7.5e8, 1020.0, true, 0.0});
  CatenaryLine friction("friction", m, {0, Vector3(420, 0, -150)}, {1, Vector3(20, 0, 0)},
                        {500.0, 7.5e8, 1020.0, true, 1.0});
  Rig r(m, {&taut, &friction});
  r.q << 0.5, 0.2, 0.1, 1.0, 0.0, 0.0, 0.0;
  r.v.setConstant(0.1);
  r.step(1e-2);
  const Stage s = r.stage();
  dynamics::ExternalForces f(m);
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(m.nv);
  const std::size_t before = allocationCount();
  double sink = 0.0;
  for (ForceProvider* fp : std::initializer_list<ForceProvider*>{&taut, &friction}) {
    fp->evaluate(s, f, tau);
    sink += fp->potentialEnergy(s) + fp->power(s);
  }
  sink += taut.fairleadStiffness(s).norm() + friction.state(s).solution.laidLength;
  CHECK(allocationCount() == before);
  CHECK(std::isfinite(sink));
}

TEST_CASE("a lumped line's node forces and masses do not allocate") {
  LumpedLineProperties p;
  p.length = 100.0;
  p.segments = 10;
  p.diameter = 0.1;
  p.massPerLength = 80.0;
  p.ea = 5e8;
  p.damping = -0.5;
  p.cdn = 1.2;
  p.cdt = 0.4;
  p.can = 1.0;
  p.cat = 0.1;
  p.seabed = true;
  p.seabedZ = -60.0;
  p.bedStiffness = 1e6;
  p.bedFriction = 0.5;
  WaterProperties water;
  water.depth = 60.0;
  const AiryWaves waves(water, {{2.0, 8.0, 0.0, 0.0}});
  CurrentProperties cp;
  cp.speed = 0.5;
  const CurrentField current(cp);
  const LumpedLine line(p, "line", &waves, &current);
  Eigen::Matrix3Xd r(3, 11), v(3, 11), f(3, 11);
  for (int i = 0; i <= 10; ++i) r.col(i) = Vector3(9.0 * i, 0.0, -60.0 + 5.0 * i);
  v.setConstant(0.1);
  Eigen::VectorXd tension(10);
  std::vector<dynamics::Matrix3> m(11);
  const std::size_t before = allocationCount();
  line.nodeForces(r, v, 1.0, f, tension);
  line.nodeMass(r, 0.0, m);
  const double e = line.potentialEnergy(r, 0.0);
  CHECK(allocationCount() == before);
  CHECK(std::isfinite(e + f.sum() + tension.sum() + m[3].sum()));
}

namespace {

// (a scene's system, its providers of registered readers) => the allocations of 10 rounds of
// their evaluate, energy and power, each with its scratch, at q0 with every velocity 0.1 and the
// time moving, after one round of set-up; sink gets what they gave
std::size_t contributedAllocations(const mechanics::System& sys, double& sink) {
  const dynamics::Model& m = sys.model();
  const Eigen::VectorXd q = sys.description().q0, v = Eigen::VectorXd::Constant(m.nv, 0.1);
  dynamics::Data kin(m);
  dynamics::forwardKinematics(m, kin, q, v);
  std::vector<std::unique_ptr<ProviderScratch>> scratch;  // (the caller's, made once)
  for (const auto& p : sys.contributed()) scratch.push_back(p->makeScratch());
  dynamics::ExternalForces f(m);
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(m.nv);
  std::size_t before = 0;
  for (int round = 0; round <= 10; ++round) {
    if (round == 1) before = allocationCount();
    for (std::size_t k = 0; k < scratch.size(); ++k) {
      const ForceProvider& p = *sys.contributed()[k];
      const Stage s{0.01 * round, m, kin, q, v, scratch[k].get()};
      p.evaluate(s, f, tau);
      sink += p.potentialEnergy(s) + p.power(s);
    }
  }
  const std::size_t n = allocationCount() - before;
  sink += tau.norm();
  return n;
}

}  // namespace

TEST_CASE("lumped mooring lines and lumped crane ropes do not allocate at a stage") {
  // (a buoy on 4 lumped chains, partly on the bed; a block hoisted by a lumped rope from a fixed
  // point and held by one over a carrier's sheave: spans, the segment over the sheave, p and q)
  const mechanics::System moored(
      yardsim::testing::buildFromScene(yardsim::testing::mooredBuoyScene()), {}, "test");
  const mechanics::System crane(yardsim::testing::buildFromScene(R"(schema_version: 1
integrator: {method: rk4, dt: 0.001}
mechanics:
  bodies:
    carrier: {parent: world, joint: {type: prismatic, axis: [1, 0, 0]}, placement: {xyz: [0, 0, 30]},
              mass: 500, inertia: [1, 1, 1]}
    block: {parent: world, joint: {type: prismatic, axis: [0, 0, 1], q0: 12},
            placement: {xyz: [4, 0, 0]}, mass: 2000, inertia: [1, 1, 1]}
  ropes:
    hoist: {model: lumped, path: [{point: [-3, 0, 12]}, {body: carrier, point: [0, 0, 0.5]},
            {body: block}], L0: 36, segments: 7, EA: 2.0e6, mass_per_length: 10, diameter: 0.04,
            EI: 2.0e5}
    tag: {model: lumped, path: [{point: [8, 0, 30]}, {body: block}], L0: 20, segments: 6,
          EA: 2.0e6, mass_per_length: 10, diameter: 0.04}
until: 1
)"),
                                {}, "test");
  REQUIRE(moored.contributed().size() == 4);
  REQUIRE(crane.contributed().size() == 2);
  const auto overSheave = [](const auto& p) {
    return dynamic_cast<const ObservedProvider<LumpedRopeOverSheave>*>(p.get()) != nullptr;
  };
  REQUIRE(overSheave(crane.contributed()[0]) != overSheave(crane.contributed()[1]));
  double sink = 0.0;
  CHECK(contributedAllocations(moored, sink) == 0);
  CHECK(contributedAllocations(crane, sink) == 0);
  CHECK(std::isfinite(sink));
  CHECK(sink != 0.0);
}
