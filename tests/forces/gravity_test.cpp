// Gravity as a provider: with model gravity zero it reproduces the kernel's own gravity (a free
// body in free fall, a double pendulum), the centre of mass falls by g t^2 / 2, the potential
// energy is the kernel's, and kinetic + potential stays constant.
#include <catch2/catch.hpp>

#include <stdexcept>

#include "dynamics/rotation.hpp"
#include "force_rig.hpp"
#include "forces/gravity.hpp"

using namespace yardsim;
using namespace yardsim::forces;
using namespace yardsim::forces::testing;
using dynamics::Matrix3;

namespace {

const Vector3 kG(0.0, 0.0, -9.81);

dynamics::Model freeBody(const Vector3& gravity) {
  dynamics::ModelBuilder b;
  b.setGravity(gravity);
  Matrix3 I;
  I << 4.0, 0.3, -0.2, 0.3, 6.0, 0.1, -0.2, 0.1, 9.0;
  b.addBody("block", "world", dynamics::Joint::free(), dynamics::Transform::identity(),
            dynamics::makeInertia(120.0, Vector3(0.3, -0.2, 0.5), I));
  return b.build();
}

dynamics::Model doublePendulum(const Vector3& gravity) {
  dynamics::ModelBuilder b;
  b.setGravity(gravity);
  b.addBody("upper", "world", dynamics::Joint::revolute(Vector3::UnitY()),
            dynamics::Transform::identity(),
            dynamics::makeInertia(3.0, Vector3(0.1, 0.0, -0.6), 0.2 * Matrix3::Identity()));
  b.addBody("lower", "upper", dynamics::Joint::revolute(Vector3::UnitY()),
            dynamics::Transform::translation(Vector3(0.0, 0.0, -1.2)),
            dynamics::makeInertia(2.0, Vector3(0.0, 0.05, -0.5), 0.1 * Matrix3::Identity()));
  return b.build();
}

}  // namespace

TEST_CASE("a free body falls under the provider as under the kernel's gravity") {
  const dynamics::Model withProvider = freeBody(Vector3::Zero()), withModel = freeBody(kG);
  Gravity gravity("gravity", kG);
  Rig a(withProvider, {&gravity}), b(withModel, {});
  // (a tilted, spinning, moving start) => the same in both
  Eigen::VectorXd q0(7), v0(6);
  q0 << 1.0, -2.0, 30.0, 0.0, 0.0, 0.0, 0.0;
  dynamics::matrixToQuaternion(dynamics::axisRotation(Vector3(1, 2, 3).normalized(), 0.7),
                               q0.data() + 3);
  v0 << 0.4, -0.3, 1.1, 2.0, 0.5, 3.0;
  a.q = b.q = q0;
  a.v = b.v = v0;
  dynamics::Data d(withProvider);
  const Vector3 c0 = dynamics::centerOfMass(withProvider, d, q0);
  dynamics::forwardKinematics(withProvider, d, q0, v0);
  const Vector3 cdot0 = dynamics::pointVelocity(d, 1, withProvider.inertias[1].com);
  const double h = 1e-3;
  for (int k = 0; k < 1000; ++k) {
    a.step(h);
    b.step(h);
  }
  CHECK((a.q - b.q).cwiseAbs().maxCoeff() < 1e-10);
  CHECK((a.v - b.v).cwiseAbs().maxCoeff() < 1e-10);
  // (closed form) => the centre of mass follows c0 + c'0 t + g t^2 / 2
  const Vector3 expected = c0 + cdot0 * a.t + 0.5 * kG * a.t * a.t;
  CHECK((dynamics::centerOfMass(withProvider, d, a.q) - expected).norm() < 1e-9);
}

TEST_CASE("a double pendulum swings as under the kernel gravity with constant energy") {
  const dynamics::Model withProvider = doublePendulum(Vector3::Zero()),
                        withModel = doublePendulum(kG);
  Gravity gravity("gravity", kG);
  Rig a(withProvider, {&gravity}), b(withModel, {});
  a.q << 1.2, -0.7;
  b.q = a.q;
  a.v << 0.5, 1.0;
  b.v = a.v;
  // (the kernel's own potential) => the provider's, at the start
  dynamics::Data d(withModel);
  CHECK(gravity.potentialEnergy(a.stage()) ==
        Approx(dynamics::potentialEnergy(withModel, d, b.q)).epsilon(1e-14));
  CHECK(gravity.power(a.stage()) == 0.0);
  const double e0 = a.energy(), scale = 5.0 * 9.81 * 2.4;
  double drift = 0.0;
  for (int k = 0; k < 2000; ++k) {
    a.step(1e-3);
    b.step(1e-3);
    drift = std::max(drift, std::abs(a.energy() - e0));
  }
  CHECK((a.q - b.q).cwiseAbs().maxCoeff() < 1e-10);
  CHECK((a.v - b.v).cwiseAbs().maxCoeff() < 1e-10);
  CHECK(drift / scale < 1e-8);
}

TEST_CASE("gravity adds m g at each centre of mass and refuses a non-finite g") {
  const dynamics::Model m = doublePendulum(Vector3::Zero());
  Gravity gravity("gravity", kG);
  Rig r(m, {&gravity});
  r.q << 0.4, 0.9;
  dynamics::ExternalForces f(m);
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(m.nv);
  const Stage s = r.stage();
  gravity.evaluate(s, f, tau);
  for (int b = 1; b < m.nbodies; ++b) {
    const Vector3 p_W = s.data.X_WB[b].actPoint(m.inertias[b].com);
    const dynamics::Force F = f.worldFrame(b);
    CHECK((F.tail<3>() - m.inertias[b].mass * kG).norm() < 1e-12);
    CHECK((F.head<3>() - p_W.cross(m.inertias[b].mass * kG)).norm() < 1e-12);
  }
  CHECK(tau.isZero());
  CHECK_THROWS_AS(Gravity("bad", Vector3(0.0, std::nan(""), 0.0)), std::invalid_argument);
}
