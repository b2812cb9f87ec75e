// Once set up, a stage of a system with ropes and an equalizer allocates nothing: the providers'
// scratch is made once in mechanics::Data and handed over at every stage; nor does a stage that
// writes the added mass following a hull's draft or the node masses of a lumped rope under a
// winch, nor a step of any integrator on a system with lumped lines (HHT and generalized-alpha
// through their sparse Newton matrix, the SUNDIALS methods through the chart Newton system, and
// through SUNDIALS' own dense difference-quotient Jacobian).
#include <catch2/catch.hpp>

#include "dynamics/integrators/adaptive_integrator.hpp"
#include "dynamics/integrators/factory.hpp"
#include "forces/geometry/mesh_io.hpp"
#include "forces/geometry/primitive_meshes.hpp"
#include "mechanics/energy.hpp"
#include "support/allocation_counter.hpp"
#include "support/scene_files.hpp"
#include "tests/mechanics/mechanics_fixture.hpp"

using namespace yardsim;

namespace {

// (a staged system, its start and velocity, a step's change of q before each stage) => the
// allocations of 10 stages with the energy and the power, after one stage of set-up
std::size_t stageAllocations(testing::StagedSystem& s, Eigen::VectorXd q, const Eigen::VectorXd& v,
                             double dz = 0.0) {
  Eigen::VectorXd a(s.model().nv);
  s.data.kernel.acceleration(0.0, q, v, a);  // set-up
  double sink = 0.0;
  const std::size_t before = testing::allocationCount();
  for (int k = 1; k <= 10; ++k) {
    q[2] += dz;
    s.data.kernel.acceleration(0.01 * k, q, v, a);
    sink += a.sum() + mechanics::energy(s.system, s.data, s.data.view, q, v, 0.01 * k) +
            mechanics::nonConservativePower(s.system, s.data, s.sp, q, v, 0.01 * k);
  }
  const std::size_t n = testing::allocationCount() - before;
  CHECK(std::isfinite(sink));
  return n;
}

// (scene, method, SUNDIALS' dense Newton) => its staged system and integrator (dt 0.01 s) after 5
// steps of set-up from the scene's q0, v0 (a multistep start, CVODE's and ARKODE's first order
// and step size)
struct SetUpRun {
  testing::StagedSystem s;
  dynamics::IntegratorSpec spec;
  std::unique_ptr<dynamics::Integrator> integrator;
  Eigen::VectorXd q, v;
  double t = 0.0;
  SetUpRun(const std::string& scene, std::string_view method, bool denseNewton = false)
      : s(testing::buildFromScene(scene)),
        spec(specOf(method)),
        integrator(dynamics::makeIntegrator(spec, s.model())),
        q(s.system.description().q0),
        v(s.system.description().v0) {
    if (auto* adaptive = dynamic_cast<dynamics::AdaptiveIntegrator*>(integrator.get()))
      adaptive->useDenseNewton(denseNewton);
    for (int k = 0; k < 5; ++k) step();
  }
  static dynamics::IntegratorSpec specOf(std::string_view method) {
    dynamics::IntegratorSpec spec;
    spec.method = std::string(method);
    spec.dt = 0.01;
    return spec;
  }
  void step() { integrator->step(s.data.kernel, t, q, v, spec.dt); }
  // (wait for a Jacobian) => 10 steps, then more until the integrator's next Jacobian (2000 at
  // most); the heap blocks they allocated, their count in steps
  int steps = 0;
  std::size_t blocksInSteps(bool waitForJacobian) {
    const long jacobians = integrator->stats().jac_evals;
    const std::size_t before = testing::allocationCount();
    steps = 0;
    while (steps < 10 ||
           (waitForJacobian && integrator->stats().jac_evals == jacobians && steps < 2000)) {
      step();
      ++steps;
    }
    return testing::allocationCount() - before;
  }
};

}  // namespace

TEST_CASE("a stage, the energy and the power allocate nothing once the system is set up") {
  testing::StagedSystem s(testing::buildFromYaml(testing::kHoistAndEqualizer));
  const Eigen::VectorXd v = Eigen::VectorXd::Constant(s.model().nv, 0.1);
  CHECK(stageAllocations(s, s.system.description().q0, v) == 0);
}

TEST_CASE("a stage writing the added mass that follows a hull's draft allocates nothing") {
  // (a 20 x 8 x 4 m box whose added mass follows its draft, half in the water, heaving) => each
  // stage interpolates its A-infinity into the kernel's, the servos' and the reactions' workspaces
  // (mechanics/follow_draft.hpp), and the energy into its own, without allocating
  testing::SceneDir dir;
  forces::writeObj(forces::boxMesh(dynamics::Vector3(20, 8, 4), 10, 4, 4), dir.file("box.obj"));
  testing::StagedSystem s(testing::buildFromYaml(R"(bodies:
  box:
    parent: world
    joint: {type: free, q0: {xyz: [0, 0, 0.3]}}
    mass: 4.0e5
    inertia: [2.7e6, 1.4e7, 1.5e7]
    added_mass: {hull: )" + dir.file("box.obj") + R"(, follow_draft: [1.0, 2.0, 3.0]}
)"));
  REQUIRE(s.system.draftAddedMass().size() == 1);
  const Eigen::VectorXd v = Eigen::VectorXd::Constant(s.model().nv, -0.1);  // sinking
  // (through the table's drafts: 1.7 .. 2.7 m)
  CHECK(stageAllocations(s, s.system.description().q0, v, -0.1) == 0);
  CHECK(s.data.kernel.data().hasAddedMass[1]);  // (wet: the written added mass is on)
}

TEST_CASE("a stage writing the node masses of a lumped rope under a winch allocates nothing") {
  // (a 2 t block hanging on 20 m of lumped rope, 8 segments, hauled in at 0.4 m/s from t = 0) =>
  // each stage writes its nodes' masses at t into the kernel's, the servos' and the reactions'
  // workspaces (mechanics/follow_mass.hpp), and the energy into its own, without allocating
  testing::StagedSystem s(testing::buildFromScene(testing::hangingRopeScene(20.0)));
  REQUIRE(s.system.winchedLines().size() == 1);
  s.system.winches().at(0).winch->setPayoutRate(0.0, -0.4);
  const Eigen::VectorXd v = Eigen::VectorXd::Constant(s.model().nv, 0.1);
  CHECK(stageAllocations(s, s.system.description().q0, v) == 0);
  CHECK(s.data.kernel.data().hasAddedMass[static_cast<std::size_t>(
      s.model().bodyIndex("hoist.node4"))]);  // (hauled in: the written mass is on)
}

TEST_CASE("every integrator steps a buoy moored by lumped lines without allocating") {
  // (4 chains of 8 segments: 86 dofs; HHT and generalized-alpha form F_q, F_v by colours with
  // the lines' blocks in closed form and factorise by the bordered band LU, and so do CVODE's and
  // ARKODE's implicit methods through the chart Newton system instead of SUNDIALS' dense
  // difference quotients) => after 5 steps of set-up (a multistep start, CVODE's and ARKODE's
  // first order and step size) 10 steps, from the buoy's release at 0.5 m/s, allocate nothing,
  // SUNDIALS included
  for (const dynamics::MethodInfo& method : dynamics::integratorMethods()) {
    INFO(method.name);
    SetUpRun run(testing::mooredBuoyScene(), method.name);
    REQUIRE(run.s.data.kernel.jacobianPattern() != nullptr);
    const auto& integrator = run.integrator;
    const Eigen::VectorXd& q = run.q;
    const long jacobians = integrator->stats().jac_evals;
    const long factorisations = integrator->stats().factorisations;
    const std::size_t before = testing::allocationCount();
    for (int k = 0; k < 10; ++k) run.step();
    const std::size_t blocks = testing::allocationCount() - before;
    INFO(blocks << " heap blocks in 10 steps, " << integrator->stats().jac_evals - jacobians
                << " Jacobians among them");
    CHECK(blocks == 0);
    // (SUNDIALS' implicit methods) => Jacobians were formed in those steps (ARKODE's), or the
    // linear system was set up again with the lines' blocks (CVODE's, which with lumped lines
    // forms a coloured Jacobian only after a failed Newton solve or every 1000 steps; its
    // formation is ARKODE's, ChartNewtonSystem::form)
    if (method.adaptive && method.implicit)
      CHECK((integrator->stats().jac_evals > jacobians ||
             (method.name.starts_with("cvode") &&
              integrator->stats().factorisations > factorisations)));
    CHECK(q[0] > 0.07);  // (the buoy moved: 0.15 s at about 0.5 m/s)
  }
}

TEST_CASE("SUNDIALS' dense Newton steps a buoy moored by lumped lines without allocating") {
  // (the moored buoy, CVODE's and ARKODE's implicit methods kept on SUNDIALS' dense path:
  // difference-quotient Jacobians, one empty N_Vector each from the integrator's pool, and dense
  // LU) => after 5 steps of set-up, the next 10 steps allocate nothing, nor those up to the next
  // Jacobian
  for (const dynamics::MethodInfo& method : dynamics::integratorMethods()) {
    if (!(method.adaptive && method.implicit)) continue;
    INFO(method.name);
    SetUpRun run(testing::mooredBuoyScene(), method.name, true);
    const auto& integrator = run.integrator;
    const long jacobians = integrator->stats().jac_evals;
    const std::size_t blocks = run.blocksInSteps(true);
    INFO(blocks << " heap blocks in " << run.steps << " steps, "
                << integrator->stats().jac_evals - jacobians << " Jacobians among them");
    CHECK(blocks == 0);
    CHECK(integrator->stats().jac_evals > jacobians);
  }
}

TEST_CASE("every integrator steps a buoy moored by catenary lines without allocating") {
  // (two quasi-static catenary lines: the implicit methods' dense Newton matrices take the lines'
  // linearisation, CVODE's and ARKODE's through their own Jacobian function instead of SUNDIALS'
  // difference quotients) => after 5 steps of set-up, the next 10 steps allocate nothing, nor
  // those up to CVODE's and ARKODE's next Jacobian
  for (const dynamics::MethodInfo& method : dynamics::integratorMethods()) {
    INFO(method.name);
    SetUpRun run(testing::catenaryBuoyScene("{method: rk4, dt: 0.01}", 8.0), method.name);
    REQUIRE(run.s.data.kernel.linearises());
    const auto& integrator = run.integrator;
    const long jacobians = integrator->stats().jac_evals;
    const bool sundialsNewton = method.adaptive && method.implicit;
    const std::size_t blocks = run.blocksInSteps(sundialsNewton);
    INFO(blocks << " heap blocks in " << run.steps << " steps, "
                << integrator->stats().jac_evals - jacobians << " Jacobians among them");
    CHECK(blocks == 0);
    // (CVODE's and ARKODE's implicit methods) => a Jacobian was formed among them through
    // AdaptiveIntegrator::denseJacobian (HHT and generalized-alpha keep their first one here)
    if (sundialsNewton) CHECK(integrator->stats().jac_evals > jacobians);
    CHECK(run.q[0] < 8.0 - 1e-3);  // (the buoy moved back toward its equilibrium)
  }
}
