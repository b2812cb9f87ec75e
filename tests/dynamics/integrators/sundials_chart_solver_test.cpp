// CVODE and ARKODE with the chart Newton system as their linear solver (sundials_chart_solver.hpp:
// a system with lumped-mass lines, whose Jacobian has a pattern) against the same solvers with
// SUNDIALS' dense difference-quotient Jacobian and dense LU (useDenseNewton), on a buoy moored
// by four lumped chain lines (86 dofs): the trajectories agree within the tolerances' scale, on
// sliders and on a free joint (a floating buoy turning: the quaternion chart's kinematics in the
// elimination), and the stage evaluations per step drop below a bound that the dense path,
// one evaluation per state component at each Jacobian, cannot meet.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "dynamics/integrators/adaptive_integrator.hpp"
#include "dynamics/integrators/factory.hpp"
#include "tests/mechanics/mechanics_fixture.hpp"

using namespace yardsim;

namespace {

// (a scene with one system, method, dense Newton or not, steps of 0.05 s) => the final state and
// the integrator's work
struct Run {
  Eigen::VectorXd q, v;
  dynamics::IntegratorStats stats;
  double turned = 0.0;  // largest rotation of the quaternion at q[3..6] from its start, rad
};
// (quaternion: the index of a free joint's quaternion in q, or -1)
Run run(const std::string& sceneText, const std::string& method, bool dense, int steps,
        int quaternion = -1) {
  testing::StagedSystem s(testing::buildFromScene(sceneText));
  REQUIRE(s.data.kernel.jacobianPattern() != nullptr);
  dynamics::IntegratorSpec spec;
  spec.method = method;
  spec.dt = 0.05;
  const auto integrator = dynamics::makeIntegrator(spec, s.model());
  auto* adaptive = dynamic_cast<dynamics::AdaptiveIntegrator*>(integrator.get());
  REQUIRE(adaptive != nullptr);
  adaptive->useDenseNewton(dense);
  Run r{s.system.description().q0, s.system.description().v0, {}, 0.0};
  const Eigen::VectorXd q0 = r.q;
  double t = 0.0;
  for (int k = 0; k < steps; ++k) {
    integrator->step(s.data.kernel, t, r.q, r.v, spec.dt);
    if (quaternion >= 0) {
      const double dot = std::abs(r.q.segment<4>(quaternion).dot(q0.segment<4>(quaternion)));
      r.turned = std::max(r.turned, 2.0 * std::acos(std::min(1.0, dot)));
    }
  }
  CHECK(t == Approx(0.05 * steps));
  r.stats = integrator->stats();
  return r;
}

// (zero gravity, four lines of 8 segments from anchors 325 m out to fairleads 10 m off the centre
// of a 200 t buoy on a free joint, taut: 314 m unstretched, 317 m apart) => the buoy, released
// drifting and turned by 10 deg in yaw, is pulled back and twisted by the lines (a torsional
// period of about 0.7 s)
std::string floatingBuoyScene() {
  std::string s = R"(schema_version: 1
integrator: {method: cvode_bdf, dt: 0.05, stiffness_check: off}
mechanics:
  gravity: [0, 0, 0]
  bodies:
    buoy: {parent: world, joint: {type: free, q0: {xyz: [0, 0, 39], rpy_deg: [2, -3, 10]},
           v0: [0.02, -0.01, 0.0, 0.4, 0.2, 0.0]}, mass: 2.0e5, inertia: [4.0e6, 4.0e6, 6.0e6]}
  mooring:
)";
  for (int k = 0; k < 4; ++k) {
    const double a = k * M_PI / 2.0 + 0.3;
    s += "    line" + std::to_string(k) + ": {model: lumped, anchor: [" +
         std::to_string(325.0 * std::cos(a)) + ", " + std::to_string(325.0 * std::sin(a)) +
         ", 0], fairlead: {body: buoy, point: [" + std::to_string(10.0 * std::cos(a)) + ", " +
         std::to_string(10.0 * std::sin(a)) +
         ", 0]}, length: 314, EA: 1.2e9, mass: 282.21, diameter: 0.216, segments: 8}\n";
  }
  return s + "until: 1\n";
}

// (two runs) => the largest difference of q and of v
double qDiff(const Run& a, const Run& b) {
  return (a.q - b.q).lpNorm<Eigen::Infinity>();
}
double vDiff(const Run& a, const Run& b) {
  return (a.v - b.v).lpNorm<Eigen::Infinity>();
}

}  // namespace

TEST_CASE(
    "CVODE BDF with the chart Newton system follows its dense path on a buoy moored by lumped "
    "lines, with fewer stage evaluations") {
  // (2 s from the release at 0.5 m/s, default tolerances rtol 1e-6, atol 1e-8) => the same
  // motion: positions (up to 300 m) within 1e-5 m, velocities within 1e-4 m/s, inside the
  // tolerances' scale (rtol |q| ~ 3e-4 m) and far below the motion (1 m, 0.5 m/s): the two
  // differ by their Newton iterates, which CVODE stops at a fraction of the local error test
  const std::string scene = testing::mooredBuoyScene();
  const int steps = 40;
  const Run sparse = run(scene, "cvode_bdf", false, steps),
            dense = run(scene, "cvode_bdf", true, steps);
  INFO("q " << qDiff(sparse, dense) << " m, v " << vDiff(sparse, dense) << " m/s; buoy at "
            << sparse.q[0] << " m");
  CHECK(sparse.q[0] > 0.3);  // (the buoy moved)
  CHECK(qDiff(sparse, dense) < 1e-5);
  CHECK(vDiff(sparse, dense) < 1e-4);
  // (work) => a Jacobian costs 2 x colours evaluations instead of 2 nv = 172: per step of the
  // grid far fewer stage evaluations; the bound lies between the two
  const double perStepSparse = static_cast<double>(sparse.stats.f_evals) / steps;
  const double perStepDense = static_cast<double>(dense.stats.f_evals) / steps;
  INFO("stage evaluations per step: sparse " << perStepSparse << " (" << sparse.stats.jac_evals
                                             << " Jacobians), dense " << perStepDense << " ("
                                             << dense.stats.jac_evals << " Jacobians)");
  CHECK(sparse.stats.jac_evals >= 1);
  CHECK(perStepSparse < 40.0);
  CHECK(perStepDense > 40.0);
}

TEST_CASE(
    "CVODE BDF with the chart Newton system follows its dense path on a floating buoy (free joint) "
    "that the lines turn") {
  const std::string scene = floatingBuoyScene();
  const int steps = 40;
  // (the buoy's quaternion: q[3..6]) => it turned by many degrees from its start: its chart's
  // kinematics (CVODE continues on one chart while it turns less than 1 rad) is far from I
  const Run sparse = run(scene, "cvode_bdf", false, steps, 3),
            dense = run(scene, "cvode_bdf", true, steps, 3);
  INFO("q " << qDiff(sparse, dense) << ", v " << vDiff(sparse, dense) << "; turned by up to "
            << sparse.turned * 180.0 / M_PI << " deg, Newton its " << sparse.stats.newton_its
            << " / " << dense.stats.newton_its << ", failures " << sparse.stats.err_fails << " / "
            << dense.stats.err_fails << ", evaluations " << sparse.stats.f_evals << " / "
            << dense.stats.f_evals);
  CHECK(sparse.turned > 10.0 * M_PI / 180.0);
  CHECK(qDiff(sparse, dense) < 1e-5);
  CHECK(vDiff(sparse, dense) < 1e-4);
  CHECK(sparse.stats.f_evals < dense.stats.f_evals / 2);
}

TEST_CASE(
    "CVODE Adams and ARKODE's implicit methods with the chart Newton system follow their dense "
    "paths") {
  const std::string scene = testing::mooredBuoyScene();
  for (const char* method : {"cvode_adams", "arkode_dirk", "arkode_imex"}) {
    INFO(method);
    const int steps = 10;
    const Run sparse = run(scene, method, false, steps), dense = run(scene, method, true, steps);
    INFO("q " << qDiff(sparse, dense) << " m, v " << vDiff(sparse, dense) << " m/s; evaluations "
              << sparse.stats.f_evals << " / " << dense.stats.f_evals);
    CHECK(sparse.q[0] > 0.2);
    CHECK(qDiff(sparse, dense) < 1e-5);
    CHECK(vDiff(sparse, dense) < 1e-4);
    CHECK(sparse.stats.f_evals < dense.stats.f_evals);
  }
}
