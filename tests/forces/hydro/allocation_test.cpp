// The hydrodynamic providers allocate nothing once built: the rankine_td provider at a stage and
// at a panel step, the impulse-response force at a stage and a commit of its memory; every heap
// allocation counted. (The added mass following a draft:
// tests/mechanics/stage_allocation_test.cpp.)
#include <catch2/catch.hpp>

#include "support/allocation_counter.hpp"

#include <vector>

#include "forces/force_rig.hpp"
#include "forces/hydro/hull_shapes.hpp"
#include "forces/hydro/impulse_response_force.hpp"
#include "forces/hydro/irregular_sea.hpp"
#include "forces/hydro/rankine_td_provider.hpp"

using yardsim::testing::allocationCount;

using namespace yardsim;
using namespace yardsim::forces;
using namespace yardsim::forces::testing;

TEST_CASE("the rankine_td provider allocates nothing at a stage or a panel step") {
  // (a stage, a panel step: the product with the mixed problem's solution map) => no heap block
  // (before 2026-11-29 PartialPivLU::solve on an N x 1 matrix took Eigen's blocked triangular
  // solves, whose packing blocks above EIGEN_STACK_ALLOCATION_LIMIT came from the heap)
  dynamics::ModelBuilder b;
  b.setGravity(Vector3::Zero());
  b.addBody("float", "world", dynamics::Joint::free(), dynamics::Transform::identity(),
            dynamics::boxInertia(2e3, Vector3(2, 2, 1)));
  const dynamics::Model m = b.build();
  hydro::RankineTdSettings settings;
  settings.freeSurface.truncationRadius = 8.0;
  settings.freeSurface.firstSpacing = 0.3;
  settings.freeSurface.maxSpacing = 1.0;
  settings.freeSurface.dampingWidth = 3.0;
  settings.freeSurface.dampingStrength = 1.0;
  const auto panels = std::make_shared<const hydro::RankineTdModel>(
      hydro::cubeSphere(1.0, 4), dynamics::Transform{}, settings);
  const hydro::RankineTdProvider radiation("radiation", m, 1, panels, 0.1);
  Rig r(m, {});
  r.v[2] = 0.3;  // moving, so that the march has something to do
  const Stage s = r.stage();
  dynamics::ExternalForces f(m);
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(m.nv);
  auto scratch = radiation.makeScratch();
  double sink = 0.0;
  const std::size_t before = allocationCount();
  for (int n = 0; n < 6; ++n) {
    // (a step's first stage at t = n dt / 2: a panel step every other one) => evaluate and power
    Stage own = s;
    own.t = own.stepStart = 0.05 * n;
    own.scratch = scratch.get();
    radiation.evaluate(own, f, tau);
    own.t += 0.025;
    radiation.evaluate(own, f, tau);
    sink += radiation.power(own);
  }
  const std::size_t blocks = allocationCount() - before;
  INFO(blocks << " heap blocks in 3 panel steps and 12 stages");
  CHECK(blocks == 0);
  CHECK(sink != 0.0);
}

TEST_CASE("the impulse-response force does not allocate at a stage") {
  dynamics::ModelBuilder b;
  b.setGravity(Vector3::Zero());
  b.addBody("barge", "world", dynamics::Joint::free(), dynamics::Transform::identity(),
            dynamics::boxInertia(3e5, Vector3(20, 8, 4)));
  const dynamics::Model m = b.build();
  // (60 s of memory at 0.05 s, one heading, a sea of 50 components)
  auto ir = std::make_shared<hydro::ImpulseResponse>();
  ir->dt = 0.05;
  ir->radiation.assign(1200, hydro::ImpulseResponse::Matrix6::Identity());
  ir->headings = {0.0};
  ir->excitationStart = -2.0;
  ir->excitation.assign(
      1, std::vector<hydro::ImpulseResponse::Vector6>(80, hydro::ImpulseResponse::Vector6::Ones()));
  hydro::IrregularSea spec;
  spec.hs = 2.0, spec.tp = 8.0, spec.components = 50;
  const auto sea =
      std::make_shared<const AiryWaves>(WaterProperties{}, hydro::irregularWaves(spec));
  const hydro::ImpulseResponseForce p("radiation", m, 1, ir, sea);
  auto scratch = p.makeScratch();
  dynamics::Data data(m);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(m.nq), v = Eigen::VectorXd::Constant(m.nv, 0.1);
  q[3] = 1.0;
  dynamics::forwardKinematics(m, data, q, v);
  dynamics::ExternalForces f(m);
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(m.nv);
  p.evaluate(Stage{0.0, m, data, q, v, scratch.get(), 0.0}, f, tau);  // (the first commit)
  std::vector<double> carried;  // (a checkpoint's buffer, the caller's)
  carried.reserve(20000);
  const std::size_t before = allocationCount();
  double sink = 0.0;
  for (int i = 1; i < 50; ++i) {  // (commits at the steps' starts, stages between, a step again)
    const double t = 0.04 * i;
    p.evaluate(Stage{t, m, data, q, v, scratch.get(), t}, f, tau);
    p.evaluate(Stage{t + 0.02, m, data, q, v, scratch.get(), t}, f, tau);
    sink += p.power(Stage{t + 0.04, m, data, q, v, scratch.get(), t});
  }
  p.evaluate(Stage{1.0, m, data, q, v, scratch.get(), 1.0}, f, tau);
  scratch->carried(carried);
  scratch->restoreCarried(carried);
  CHECK(allocationCount() == before);
  CHECK(carried.size() > 7200);
  CHECK(std::isfinite(sink));
  CHECK(sink != 0.0);
}
