// ABA cross-checks: against CRBA + dense solve, and RNEA(ABA(tau)) = tau, on random trees with
// every joint type, with and without external forces.
#include <catch2/catch.hpp>

#include <Eigen/Cholesky>

#include "dynamics/aba.hpp"
#include "dynamics/configuration.hpp"
#include "dynamics/crba.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/rnea.hpp"
#include "test_models.hpp"

using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;

TEST_CASE("ABA = M^-1 (tau - h) and RNEA(ABA(tau)) = tau on random trees") {
  std::mt19937 rng(17);
  for (int trial = 0; trial < 48; ++trial) {
    const int n = 1 + (trial % 12) * 3;
    // the second dozen of each kind: every other body carries a full 6x6 added mass; the last
    // two dozen: coordinate-axis joints in translated frames (the kernels' special case)
    const bool added = trial % 24 >= 12;
    const bool axes = trial >= 24;
    const Model m =
        axes ? randomAxisTree(rng, n, added) : randomTree(rng, n, {0.0, 0.0, -9.81}, added);
    INFO("bodies " << n << (added ? " with added mass" : "") << (axes ? ", coordinate axes" : ""));
    Data d(m);
    const Eigen::VectorXd q = randomConfiguration(m, rng), v = randomVectorX(rng, m.nv), tau = randomVectorX(rng, m.nv);
    ExternalForces f(m);
    for (int i = 1; i < m.nbodies; ++i) {
      if (i % 2) f.addWorldFrame(i, randomVectorX(rng, 6));
      else f.addBodyFrame(i, randomVectorX(rng, 6));
    }
    for (const ExternalForces* fext : {static_cast<const ExternalForces*>(nullptr), static_cast<const ExternalForces*>(&f)}) {
      const Eigen::VectorXd ddq = aba(m, d, q, v, tau, fext);
      const Eigen::MatrixXd M = crba(m, d, q);
      const Eigen::VectorXd h = biasForces(m, d, q, v, fext);
      const Eigen::VectorXd ref = M.ldlt().solve(tau - h);
      CHECK(relativeError(ddq, ref) < 1e-10);
      CHECK(relativeError(rnea(m, d, q, v, ddq, fext), tau) < 1e-10);
    }
  }
}

TEST_CASE("ABA of a fixed-base pendulum gives -g/l sin(theta) for a point-like bob") {
  ModelBuilder b;
  const double l = 2.0, mass = 3.0;
  b.addBody("bob", "world", Joint::revolute(Vector3::UnitY()), {},
            makeInertia(mass, Vector3(0, 0, -l), 1e-9 * Matrix3::Identity()));
  const Model m = b.build();
  Data d(m);
  Eigen::VectorXd q(1), v(1), tau(1);
  q << 0.4;
  v << 0.0;
  tau << 0.0;
  // about +y, a positive angle swings the bob towards +x: gravity pulls it back
  CHECK(aba(m, d, q, v, tau)[0] == Approx(-9.81 / l * std::sin(0.4)).epsilon(1e-8));
}

TEST_CASE("added mass slows a body's fall but adds nothing to its weight") {
  // a free body, centre of mass at its origin, heave added mass A33: released from rest it
  // accelerates at m g / (m + A33); a coupling A35 (heave-pitch, [angular; linear] entry (1, 5))
  // makes it pitch as well, as (M + A) a = (0, m g) says
  const double mass = 500.0, a33 = 300.0;
  for (const double a35 : {0.0, 40.0}) {
    ModelBuilder b;
    b.addBody("float", "world", Joint::free(), {}, boxInertia(mass, Vector3(2.0, 1.0, 1.0)));
    Matrix6 A = Matrix6::Zero();
    A(5, 5) = a33;
    A(1, 5) = A(5, 1) = a35;
    A(1, 1) = 60.0;
    b.setAddedMass("float", A);
    const Model m = b.build();
    Data d(m);
    const Eigen::VectorXd q = neutralConfiguration(m), v = Eigen::VectorXd::Zero(6), tau = Eigen::VectorXd::Zero(6);
    const Eigen::VectorXd ddq = aba(m, d, q, v, tau);
    const Matrix6 MA = boxInertia(mass, Vector3(2.0, 1.0, 1.0)).matrix() + A;
    Vector6 weight = Vector6::Zero();
    weight[5] = -9.81 * mass;
    const Vector6 expected = MA.ldlt().solve(weight);
    CHECK(relativeError(ddq, expected) < 1e-12);
    if (a35 == 0.0) CHECK(ddq[5] == Approx(-9.81 * mass / (mass + a33)));
    // RNEA gives back zero joint forces at that acceleration
    CHECK(rnea(m, d, q, v, ddq).norm() < 1e-9 * mass);
  }
}

TEST_CASE("ABA after forward kinematics equals ABA to the last bit, and does use the kinematics it is given") {
  std::mt19937 rng(23);
  for (int trial = 0; trial < 24; ++trial) {
    const Model m = randomTree(rng, 1 + (trial % 12) * 3, {0.0, 0.0, -9.81}, trial >= 12);
    Data full(m), reuse(m);
    const Eigen::VectorXd q = randomConfiguration(m, rng), v = randomVectorX(rng, m.nv), tau = randomVectorX(rng, m.nv);
    ExternalForces f(m);
    for (int i = 1; i < m.nbodies; ++i) f.addWorldFrame(i, randomVectorX(rng, 6));
    const Eigen::VectorXd a = aba(m, full, q, v, tau, &f);
    forwardKinematics(m, reuse, q, v);
    CHECK(abaAfterKinematics(m, reuse, q, v, tau, &f) == a);  // bit for bit
    // (kinematics of another configuration) => another answer: the placements are not recomputed
    const Eigen::VectorXd q2 = randomConfiguration(m, rng);
    forwardKinematics(m, reuse, q2, v);
    CHECK(relativeError(abaAfterKinematics(m, reuse, q, v, tau, &f), a) > 1e-6);
  }
}

TEST_CASE(
    "ABA on chains and floating trees of axis joints with diagonal inertias, tilted gravity, "
    "against CRBA + solve, RNEA and the accelerations of forward kinematics") {
  // the kernels' special cases together: coordinate-axis revolute and prismatic joints on a
  // free root, inertias diagonal about the centre of mass (Model::inertiaDiagonal), planar chains;
  // gravity off the z axis (ABA folds -g into the root's acceleration); A_W, which ABA leaves,
  // against forwardKinematics(q, v, ddq)'s body accelerations plus the folded -g
  std::mt19937 rng(29);
  for (int trial = 0; trial < 24; ++trial) {
    const int n = 1 + (trial % 8) * 5;
    Model m = trial < 8 ? planarChain(n) : randomAxisTree(rng, n, trial >= 16, true);
    m.gravity = Vector3(1.5, -2.0, -9.0);
    INFO("trial " << trial << ", bodies " << n);
    Data d(m), fk(m);
    const Eigen::VectorXd q = randomConfiguration(m, rng), v = randomVectorX(rng, m.nv, 2.0),
                          tau = randomVectorX(rng, m.nv);
    ExternalForces f(m);
    for (int i = 1; i < m.nbodies; ++i) {
      if (i % 3 == 0) f.addBodyFrame(i, randomVectorX(rng, 6));
      if (i % 3 == 1) f.addWorldFrame(i, randomVectorX(rng, 6));
    }
    for (const ExternalForces* fext :
         {static_cast<const ExternalForces*>(nullptr), static_cast<const ExternalForces*>(&f)}) {
      const Eigen::VectorXd ddq = aba(m, d, q, v, tau, fext);
      const std::vector<Motion> A_W = d.A_W;
      const Eigen::VectorXd h = biasForces(m, d, q, v, fext);
      const Eigen::VectorXd ref = crba(m, d, q).ldlt().solve(tau - h);
      CHECK(relativeError(ddq, ref) < 1e-10);
      // (against the size of the terms that cancel: a long chain turning fast has |h| >> |tau|)
      CHECK((rnea(m, d, q, v, ddq, fext) - tau).norm() < 1e-12 * (tau.norm() + h.norm()));
      forwardKinematics(m, fk, q, v, ddq);
      for (int i = 1; i < m.nbodies; ++i) {
        Motion expected = bodyAccelerationWorld(fk, i);
        expected.tail<3>() -= m.gravity;
        CHECK((A_W[i] - expected).norm() < 1e-10 * (1.0 + expected.norm()));
      }
    }
  }
}
