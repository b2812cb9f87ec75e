// CVODE (BDF and Adams) on the multibody state: the error follows the tolerance, statistics are
// reported, the maximum BDF order is honoured, consecutive steps continue the solver's history,
// state events are located by root finding, quaternions stay unit length, and BDF steps over a
// stiff mode that an explicit method would have to resolve.
#include <catch2/catch.hpp>

#include "dynamics/energy.hpp"
#include "dynamics/integrators/cvode.hpp"
#include "integrator_cases.hpp"

using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;

namespace {
IntegratorSpec adaptive(const std::string& method, double rtol) {
  IntegratorSpec s = specOf(method);
  s.rtol = rtol;
  s.atol = rtol * 1e-2;
  return s;
}
}  // namespace

TEST_CASE("CVODE BDF and Adams reach their tolerance on a tree with a free joint, and report statistics") {
  const SmoothTree p;
  for (const char* method : {"cvode_bdf", "cvode_adams"}) {
    INFO(method);
    // one DTSS step of T: the solver chooses its own steps inside it
    const double loose = p.error(adaptive(method, 1e-5), 1), tight = p.error(adaptive(method, 1e-9), 1);
    INFO("errors " << loose << " " << tight);
    CHECK(loose < 1e-3);
    CHECK(tight < 1e-7);
    CHECK(tight < loose / 100);
    Cvode cv(p.model, adaptive(method, 1e-8));
    MultibodySystem sys(p.model);
    Eigen::VectorXd q = p.q0, v = p.v0;
    double t = 0.0;
    cv.step(sys, t, q, v, p.T);
    CHECK(t == p.T);
    CHECK(cv.stats().steps > 10);
    CHECK(cv.stats().f_evals > cv.stats().steps);
    CHECK(cv.stats().newton_its >= cv.stats().steps);
    CHECK(cv.stats().jac_evals >= 1);
  }
}

TEST_CASE("CVODE BDF honours its maximum order: order 1 needs far more steps than order 5") {
  const SmoothTree p;
  auto steps = [&](int order) {
    IntegratorSpec s = adaptive("cvode_bdf", 1e-8);
    s.maxOrder = order;
    Cvode cv(p.model, s);
    MultibodySystem sys(p.model);
    Eigen::VectorXd q = p.q0, v = p.v0;
    double t = 0.0;
    cv.step(sys, t, q, v, p.T);
    return cv.stats().steps;
  };
  const long s1 = steps(1), s2 = steps(2), s5 = steps(5);
  INFO(s1 << " " << s2 << " " << s5);
  CHECK(s1 > 5 * s5);
  CHECK(s2 > s5);
}

TEST_CASE("CVODE continues its history over consecutive steps and restarts after reset()") {
  Oscillator osc(3.0);
  auto run = [&](bool resetEveryStep) {
    Cvode cv(osc.model, adaptive("cvode_adams", 1e-8));
    Eigen::VectorXd q = Eigen::VectorXd::Ones(1), v = Eigen::VectorXd::Zero(1);
    double t = 0.0;
    for (int k = 0; k < 100; ++k) {
      if (resetEveryStep) cv.reset();
      cv.step(osc, t, q, v, 0.02);
    }
    CHECK(q[0] == Approx(std::cos(3.0 * t)).margin(1e-6));
    return cv.stats().steps;
  };
  const long continued = run(false), restarted = run(true);
  INFO(continued << " " << restarted);
  CHECK(2 * continued < restarted);
}

TEST_CASE("CVODE root finding locates a falling mass passing 1 m below its start at sqrt(2/g)") {
  for (const char* method : {"cvode_bdf", "cvode_adams"}) {
    FallingMass fall;
    Cvode cv(fall.model, adaptive(method, 1e-10));
    cv.findRoots(true);
    Eigen::VectorXd q = Eigen::VectorXd::Zero(1), v = Eigen::VectorXd::Zero(1);
    double t = 0.0;
    cv.step(fall, t, q, v, 0.3);
    CHECK(cv.lastEvent() == -1);
    CHECK(t == 0.3);
    cv.step(fall, t, q, v, 0.3);
    CHECK(cv.lastEvent() == 0);
    CHECK(t == Approx(std::sqrt(2.0 / 9.81)).epsilon(1e-9));
    CHECK(q[0] == Approx(-1.0).epsilon(1e-9));
    // (after the root) => the next step continues to its end
    const double t1 = t;
    cv.step(fall, t, q, v, 0.1);
    CHECK(cv.lastEvent() == -1);
    CHECK(t == Approx(t1 + 0.1));
  }
}

TEST_CASE("CVODE keeps quaternions unit length and angular momentum on a spinning free body") {
  ModelBuilder b;
  b.addBody("block", "world", Joint::free(), {}, makeInertia(1.0, Vector3::Zero(), Vector3(1.0, 2.0, 3.0).asDiagonal()));
  Model m = b.build();
  m.gravity.setZero();
  Data d(m);
  MultibodySystem sys(m);
  Cvode cv(m, adaptive("cvode_bdf", 1e-9));
  Eigen::VectorXd q = neutralConfiguration(m), v = Eigen::VectorXd::Zero(6);
  v.head<3>() = Vector3(0.2, 0.1, 5.0);
  const Force h0 = momentum(m, d, q, v);
  double t = 0.0, worstNorm = 0.0;
  for (int k = 0; k < 100; ++k) {  // 25 rad about z: the chart is re-centred on the way
    cv.step(sys, t, q, v, 0.05);
    worstNorm = std::max(worstNorm, std::abs(q.segment<4>(3).norm() - 1.0));
  }
  CHECK(worstNorm < 1e-14);
  CHECK((momentum(m, d, q, v) - h0).norm() < 1e-6 * h0.norm());
}

TEST_CASE("CVODE BDF follows a slow motion through a stiff mode with far fewer steps than an explicit method could") {
  // omega = 1e4 rad/s: an explicit method needs omega h < ~3, i.e. > 3000 steps over 1 s
  Oscillator osc(1e4, 1.0);
  osc.forcing = 1.0;
  Cvode cv(osc.model, adaptive("cvode_bdf", 1e-6));
  Eigen::VectorXd q = Eigen::VectorXd::Ones(1), v = Eigen::VectorXd::Zero(1);
  double t = 0.0;
  cv.step(osc, t, q, v, 1.0);
  INFO("BDF steps " << cv.stats().steps);
  CHECK(q[0] == Approx(osc.steadyState(1.0)).margin(1e-5));
  CHECK(cv.stats().steps < 1000);
}
