// Adams-Bashforth 2-4: the order of each when the step halves, with a quaternion joint in the tree;
// one acceleration evaluation per step once started; a step that does not continue the previous
// one restarts the method (and stays accurate).
#include <catch2/catch.hpp>

#include "dynamics/integrators/adams_bashforth.hpp"
#include "integrator_cases.hpp"

using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;

TEST_CASE("Adams-Bashforth k converges with order k") {
  const SmoothTree p;
  for (int k = 2; k <= 4; ++k) {
    INFO("ab" << k);
    const double order = p.observedOrder(specOf("ab" + std::to_string(k)), 100);
    CHECK(order == Approx(k).margin(0.2));
  }
}

TEST_CASE("Adams-Bashforth 4 costs one evaluation per step after its three RK4 starting steps") {
  Oscillator osc(1.0);
  AdamsBashforth ab(osc.model, 4);
  Eigen::VectorXd q = Eigen::VectorXd::Ones(1), v = Eigen::VectorXd::Zero(1);
  double t = 0.0;
  for (int k = 0; k < 100; ++k) ab.step(osc, t, q, v, 0.01);
  // 3 starting steps: 1 history evaluation + 4 RK4 stages each; then 1 per step
  CHECK(ab.stats().f_evals == 3 * 5 + 97);
  CHECK(ab.stats().steps == 100);
  CHECK(q[0] == Approx(std::cos(1.0)).epsilon(1e-8));
}

TEST_CASE("Adams-Bashforth restarts when a step does not continue the previous one") {
  Oscillator osc(1.0);
  AdamsBashforth ab(osc.model, 3);
  Eigen::VectorXd q = Eigen::VectorXd::Ones(1), v = Eigen::VectorXd::Zero(1);
  double t = 0.0;
  for (int k = 0; k < 50; ++k) ab.step(osc, t, q, v, 0.01);
  const long before = ab.stats().f_evals;
  // (state changed from outside: an external event) => restart with RK4 steps (5 evaluations each)
  v[0] += 0.1;
  const double t0 = t, q0 = q[0], v0 = v[0];
  ab.step(osc, t, q, v, 0.01);
  CHECK(ab.stats().f_evals - before == 5);
  // (a shorter step, as when a state event is located) => restart too, and exact to RK4 accuracy
  ab.step(osc, t, q, v, 0.004);
  CHECK(ab.stats().f_evals - before == 10);
  const double A = std::hypot(q0, v0), phi = std::atan2(-v0, q0);
  CHECK(q[0] == Approx(A * std::cos(t - t0 + phi)).epsilon(1e-9));
}
