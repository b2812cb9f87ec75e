// Semi-implicit Euler: first-order convergence, bounded energy error on the pendulum, exact
// kinematics of a free body without forces.
#include <catch2/catch.hpp>

#include "dynamics/configuration.hpp"
#include "dynamics/energy.hpp"
#include "dynamics/integrators/semi_implicit_euler.hpp"
#include "dynamics/multibody_system.hpp"
#include "../test_models.hpp"

using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;

TEST_CASE("semi-implicit Euler converges with order 1") {
  const Model m = planarChain(2);
  auto solve = [&](int steps) {
    MultibodySystem sys(m);
    SemiImplicitEuler se(m);
    Eigen::VectorXd q = Eigen::VectorXd::Constant(2, 0.3), v = Eigen::VectorXd::Zero(2);
    double t = 0.0;
    for (int k = 0; k < steps; ++k) se.step(sys, t, q, v, 0.5 / steps);
    return q;
  };
  const Eigen::VectorXd ref = solve(64000);
  const double e1 = (solve(1000) - ref).norm(), e2 = (solve(2000) - ref).norm();
  INFO(e1 << " " << e2);
  CHECK(e1 / e2 > 1.8);
  CHECK(e1 / e2 < 2.2);
}

TEST_CASE("semi-implicit Euler keeps the pendulum's energy bounded (no secular drift)") {
  const Model m = planarChain(1);
  Data d(m);
  MultibodySystem sys(m);
  SemiImplicitEuler se(m);
  Eigen::VectorXd q = Eigen::VectorXd::Constant(1, 1.0), v = Eigen::VectorXd::Zero(1);
  const double E0 = potentialEnergy(m, d, q);
  Eigen::VectorXd down = Eigen::VectorXd::Constant(1, M_PI / 2);
  const double scale = E0 - potentialEnergy(m, d, down);
  double t = 0.0, firstMax = 0.0, lastMax = 0.0;
  const int n = 100000 / kScale;
  for (int k = 0; k < n; ++k) {
    se.step(sys, t, q, v, 1e-3);
    const double err = std::abs(kineticEnergy(m, d, q, v) + potentialEnergy(m, d, q) - E0) / scale;
    if (k < n / 10) firstMax = std::max(firstMax, err);
    if (k > n - n / 10) lastMax = std::max(lastMax, err);
  }
  INFO(firstMax << " " << lastMax);
  CHECK(firstMax < 1e-2);
  CHECK(lastMax < 1.5 * firstMax);
}

TEST_CASE("a torque-free free body turning about a principal axis turns uniformly") {
  ModelBuilder b;
  b.addBody("block", "world", Joint::free(), {}, boxInertia(2.0, Vector3(1, 2, 3)));
  Model m = b.build();
  m.gravity.setZero();
  MultibodySystem sys(m);
  SemiImplicitEuler se(m);
  Eigen::VectorXd q = neutralConfiguration(m), v = Eigen::VectorXd::Zero(6);
  v[2] = 0.7;  // about z
  v[3] = 1.0;  // moving along the body x axis, which turns
  double t = 0.0;
  for (int k = 0; k < 1000; ++k) se.step(sys, t, q, v, 1e-3);
  const Matrix3 R = quaternionToMatrix(q.data() + 3);
  CHECK((R - axisRotation(Vector3::UnitZ(), 0.7)).norm() < 1e-12);
}
