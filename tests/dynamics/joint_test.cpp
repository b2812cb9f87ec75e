// Each joint: S against finite differences of the joint transform, c_J against finite differences
// of S v, integrate/difference round trips, and the chart rate.
#include <catch2/catch.hpp>

#include "dynamics/joint.hpp"
#include "dynamics/rotation.hpp"
#include "test_models.hpp"

using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;

namespace {
// (X0, X1, h) => spatial velocity of the child relative to the joint frame, in the child frame
Motion relativeVelocity(const Transform& X0, const Transform& X1, double h) {
  Motion v;
  v.head<3>() = logSO3(X0.R.transpose() * X1.R) / h;
  v.tail<3>() = X0.R.transpose() * (X1.p - X0.p) / h;
  return v;
}

Eigen::VectorXd randomJointQ(const Joint& j, std::mt19937& rng) {
  Eigen::VectorXd q = randomVectorX(rng, j.nq());
  jointNormalize(j, q.data());
  return q;
}
}  // namespace

TEST_CASE("joint sizes") {
  CHECK(Joint::fixed().nq() == 0);
  CHECK(Joint::revolute().nv() == 1);
  CHECK(Joint::cylindrical().nv() == 2);
  CHECK(Joint::universal().nq() == 2);
  CHECK(Joint::planar().nv() == 3);
  CHECK(Joint::spherical().nq() == 4);
  CHECK(Joint::spherical().nv() == 3);
  CHECK(Joint::free().nq() == 7);
  CHECK(Joint::free().nv() == 6);
}

TEST_CASE("motion subspace and bias match finite differences for every joint type") {
  std::mt19937 rng(9);
  for (JointType t : allJointTypes()) {
    INFO(jointTypeName(t));
    const Joint j = jointOfType(t, rng);
    for (int k = 0; k < 5; ++k) {
      const Eigen::VectorXd q = randomJointQ(j, rng);
      const Eigen::VectorXd v = randomVectorX(rng, j.nv());
      const double h = 1e-6;
      Eigen::VectorXd qp(j.nq()), qm(j.nq());
      jointIntegrate(j, q.data(), v.data(), h, qp.data());
      jointIntegrate(j, q.data(), v.data(), -h, qm.data());
      MotionSubspace S;
      jointMotionSubspace(j, q.data(), S);
      const Motion vJ = j.nv() > 0 ? Motion(S * v) : Motion::Zero();
      const Motion fd = 0.5 * (relativeVelocity(jointTransform(j, q.data()), jointTransform(j, qp.data()), h) -
                               relativeVelocity(jointTransform(j, q.data()), jointTransform(j, qm.data()), h));
      CHECK((fd - vJ).norm() < 1e-7);
      // c_J = d/dt (S(q(t))) v at constant v, in the child frame
      MotionSubspace Sp, Sm;
      jointMotionSubspace(j, qp.data(), Sp);
      jointMotionSubspace(j, qm.data(), Sm);
      const Motion cfd = j.nv() > 0 ? Motion((Sp * v - Sm * v) / (2 * h)) : Motion::Zero();
      CHECK((jointBias(j, q.data(), v.data()) - cfd).norm() < 1e-7);
    }
  }
}

TEST_CASE("integrate and difference are inverse, chart rate matches finite differences") {
  std::mt19937 rng(10);
  for (JointType t : allJointTypes()) {
    INFO(jointTypeName(t));
    const Joint j = jointOfType(t, rng);
    const Eigen::VectorXd q0 = randomJointQ(j, rng);
    const Eigen::VectorXd d = randomVectorX(rng, j.nv(), 0.8);
    Eigen::VectorXd q1(j.nq()), d2(j.nv());
    jointIntegrate(j, q0.data(), d.data(), 1.0, q1.data());
    jointDifference(j, q0.data(), q1.data(), d2.data());
    CHECK((d2 - d).norm() < 1e-12);
    // chart: q(t) = q0 (+) theta(t), moving with v  =>  theta(t + h) = theta + h * rate
    const Eigen::VectorXd theta = randomVectorX(rng, j.nv(), 0.5), v = randomVectorX(rng, j.nv());
    Eigen::VectorXd rate(j.nv()), qa(j.nq()), qb(j.nq()), qc(j.nq()), back(j.nv());
    jointChartRate(j, theta.data(), v.data(), rate.data());
    const double h = 1e-7;
    jointIntegrate(j, q0.data(), theta.data(), 1.0, qa.data());
    jointIntegrate(j, qa.data(), v.data(), h, qb.data());      // move with v for h
    Eigen::VectorXd th2 = theta + h * rate;
    jointIntegrate(j, q0.data(), th2.data(), 1.0, qc.data());  // move the chart by rate h
    jointDifference(j, qb.data(), qc.data(), back.data());
    CHECK(back.norm() < 1e-12);
  }
}
