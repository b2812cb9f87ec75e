// Spatial algebra against its 6x6 matrix definitions (Featherstone ch. 2).
#include <catch2/catch.hpp>

#include "dynamics/spatial.hpp"
#include "test_models.hpp"

using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;

namespace {
Matrix6 crm(const Motion& v) {
  Matrix6 X = Matrix6::Zero();
  X.topLeftCorner<3, 3>() = skew(v.head<3>());
  X.bottomLeftCorner<3, 3>() = skew(v.tail<3>());
  X.bottomRightCorner<3, 3>() = skew(v.head<3>());
  return X;
}
Vector6 random6(std::mt19937& rng) { return randomVectorX(rng, 6); }
}  // namespace

TEST_CASE("cross products match crm and crf = -crm^T") {
  std::mt19937 rng(1);
  for (int k = 0; k < 20; ++k) {
    const Motion v = random6(rng), m = random6(rng);
    const Force f = random6(rng);
    CHECK((crossMotion(v, m) - crm(v) * m).norm() < 1e-14);
    CHECK((crossForce(v, f) + crm(v).transpose() * f).norm() < 1e-14);
  }
}

TEST_CASE("transforms: composition, inverse, motion/force duality") {
  std::mt19937 rng(2);
  for (int k = 0; k < 20; ++k) {
    const Transform X_AB{randomRotation(rng), randomVector(rng)}, X_BC{randomRotation(rng), randomVector(rng)};
    const Transform X_AC = X_AB * X_BC;
    const Vector3 p = randomVector(rng);
    CHECK((X_AC.actPoint(p) - X_AB.actPoint(X_BC.actPoint(p))).norm() < 1e-13);
    CHECK((X_AB.inverse().actPoint(X_AB.actPoint(p)) - p).norm() < 1e-13);
    CHECK((X_AB.invActPoint(X_AB.actPoint(p)) - p).norm() < 1e-13);
    const Motion m = random6(rng);
    const Force f = random6(rng);
    CHECK((X_AB.actMotion(m) - X_AB.motionMatrix() * m).norm() < 1e-13);
    CHECK((X_AB.invActMotion(X_AB.actMotion(m)) - m).norm() < 1e-13);
    CHECK((X_AB.invActForce(X_AB.actForce(f)) - f).norm() < 1e-13);
    // power is frame invariant: (X m) . (X^* f) = m . f
    CHECK(std::abs(X_AB.actMotion(m).dot(X_AB.actForce(f)) - m.dot(f)) < 1e-12);
    // X^* = X^-T
    CHECK((X_AB.actForce(f) - X_AB.motionMatrix().inverse().transpose() * f).norm() < 1e-12);
  }
}

TEST_CASE("spatial inertia: apply and matrix agree, transform of inertia is X^* I X^-1") {
  std::mt19937 rng(3);
  for (int k = 0; k < 20; ++k) {
    const SpatialInertia I = randomInertia(rng);
    const Motion v = random6(rng);
    CHECK((I.apply(v) - I.matrix() * v).norm() < 1e-13);
    CHECK((I.matrix() - I.matrix().transpose()).norm() < 1e-14);
    const Transform X{randomRotation(rng), randomVector(rng)};
    const Matrix6 Xm = X.motionMatrix();
    const Matrix6 expected = Xm.inverse().transpose() * I.matrix() * Xm.inverse();
    CHECK((actInertia(X, I.matrix()) - expected).norm() < 1e-12 * expected.norm());
    // a general symmetric 6x6 (articulated inertias are not rigid-body inertias)
    Matrix6 G = Matrix6::Random();
    G = (G + G.transpose()).eval();
    const Matrix6 e2 = Xm.inverse().transpose() * G * Xm.inverse();
    CHECK((actInertia(X, G) - e2).norm() < 1e-12 * e2.norm());
  }
}

TEST_CASE("kinetic energy of a rigid body from the spatial inertia equals the textbook formula") {
  std::mt19937 rng(4);
  const SpatialInertia I = randomInertia(rng);
  const Motion v = random6(rng);
  const Vector3 w = v.head<3>();
  const Vector3 vc = v.tail<3>() + w.cross(I.com);  // velocity of the centre of mass
  const double T = 0.5 * I.mass * vc.squaredNorm() + 0.5 * w.dot(I.inertiaCom * w);
  CHECK(0.5 * v.dot(I.apply(v)) == Approx(T).epsilon(1e-13));
}

TEST_CASE(
    "the world-frame inertia of a diagonal body inertia is the same with its scaling shortcut") {
  std::mt19937 rng(23);
  for (int k = 0; k < 20; ++k) {
    const SpatialInertia I =
        makeInertia(1.5, randomVector(rng), Vector3(1.0, 2.0, 2.5).asDiagonal());
    const Transform X{randomRotation(rng), randomVector(rng)};
    const Matrix6 full = I.matrixIn(X);
    CHECK((I.matrixIn<true>(X).array() == full.array()).all());
    CHECK((full - actInertia(X, I.matrix())).norm() < 1e-12);
  }
}
