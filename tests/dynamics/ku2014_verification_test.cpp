// The verification model of Ku, Ha et al. (IJCTE 6(3), 2014, Fig. 3): three bodies, three
// revolute joints, one cylindrical joint and one closed loop. The paper gives the topology and
// the 1 kg of body 1 only; we take a crank of 1 m (body 1, 1 kg), a connecting rod of 2 m
// (body 2, 1 kg) and a 1 kg slider (body 3) on a vertical cylindrical guide through the crank
// pivot, under gravity along -z, released from rest. It is built twice, cutting a different joint:
//   A: tree R1-R2-R3, the cylindrical guide is the cut (kCylinderConstraint);
//   B: trees R1-R2 and the cylindrical joint, the revolute R3 is the cut (kAxisConstraint).
// Both must give the same motion, stay closed, conserve energy and obey the slider-crank
// kinematics z = -r sin(q1) + sqrt(l^2 - r^2 cos^2(q1)).
#include <catch2/catch.hpp>

#include "dynamics/energy.hpp"
#include "dynamics/integrators/rk4.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/loop_constraints.hpp"
#include "dynamics/multibody_system.hpp"
#include "dynamics/rotation.hpp"
#include "test_models.hpp"

using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;

namespace {
constexpr double kR = 1.0, kL = 2.0;
const SpatialInertia kSlider = boxInertia(1.0, Vector3(0.2, 0.2, 0.4));

double sliderHeight(double q1) { return -kR * std::sin(q1) + std::sqrt(kL * kL - kR * kR * std::cos(q1) * std::cos(q1)); }
double rodAngle(double q1) {
  const double z = sliderHeight(q1);
  return std::atan2(-(z + kR * std::sin(q1)), -kR * std::cos(q1));
}

Model cutAtGuide() {
  ModelBuilder b;
  b.addBody("body1", "world", Joint::revolute(Vector3::UnitY()), {}, rodInertia(1.0, kR));
  b.addBody("body2", "body1", Joint::revolute(Vector3::UnitY()), Transform::translation(Vector3(kR, 0, 0)), rodInertia(1.0, kL));
  b.addBody("body3", "body2", Joint::revolute(Vector3::UnitY()), Transform::translation(Vector3(kL, 0, 0)), kSlider);
  b.addLoop("cylindrical1", "world", {}, "body3", {}, kCylinderConstraint);
  return b.build();
}

Model cutAtRevolute3() {
  ModelBuilder b;
  b.addBody("body1", "world", Joint::revolute(Vector3::UnitY()), {}, rodInertia(1.0, kR));
  b.addBody("body2", "body1", Joint::revolute(Vector3::UnitY()), Transform::translation(Vector3(kR, 0, 0)), rodInertia(1.0, kL));
  b.addBody("body3", "world", Joint::cylindrical(Vector3::UnitZ()), {}, kSlider);
  const Matrix3 zToY = axisRotation(Vector3::UnitX(), -M_PI / 2);
  b.addLoop("revolute3", "body2", Transform{zToY, Vector3(kL, 0, 0)}, "body3", Transform{zToY, Vector3::Zero()},
            kAxisConstraint);
  return b.build();
}
}  // namespace

TEST_CASE("Ku 2014 verification model: both cuts agree, stay closed, conserve energy") {
  const Model ma = cutAtGuide(), mb = cutAtRevolute3();
  REQUIRE(ma.nv == 3);
  REQUIRE(mb.nv == 4);
  const double q10 = 0.1;
  Eigen::VectorXd qa(3), qb(4), va = Eigen::VectorXd::Zero(3), vb = Eigen::VectorXd::Zero(4);
  const double phi = rodAngle(q10);
  qa << q10, phi - q10, -phi;
  qb << q10, phi - q10, 0.0, sliderHeight(q10);
  Data da(ma), db(mb);
  REQUIRE(loopResidualNorm(ma, da, qa) < 1e-14);
  REQUIRE(loopResidualNorm(mb, db, qb) < 1e-14);
  MultibodySystem sa(ma), sb(mb);
  sa.setProjection(true);
  sb.setProjection(true);
  Rk4 ra(ma), rb(mb);
  const double Ea = potentialEnergy(ma, da, qa), Eb = potentialEnergy(mb, db, qb);
  CHECK(Ea == Approx(Eb).epsilon(1e-14));
  double t = 0.0, tb = 0.0, agree = 0.0, closed = 0.0, kin = 0.0, energy = 0.0;
  for (int k = 0; k < 1000; ++k) {
    ra.step(sa, t, qa, va, 1e-3);
    rb.step(sb, tb, qb, vb, 1e-3);
    agree = std::max({agree, std::abs(qa[0] - qb[0]), std::abs(qa[1] - qb[1])});
    closed = std::max({closed, loopResidualNorm(ma, da, qa), loopResidualNorm(mb, db, qb)});
    forwardKinematics(ma, da, qa);
    kin = std::max({kin, std::abs(da.X_WB[3].p.z() - sliderHeight(qa[0])), std::abs(qb[3] - sliderHeight(qb[0]))});
    energy = std::max(energy, std::abs(kineticEnergy(ma, da, qa, va) + potentialEnergy(ma, da, qa) - Ea));
  }
  INFO("agree " << agree << " closed " << closed << " kinematics " << kin << " energy " << energy);
  CHECK(qa[0] > 1.0);  // the crank has swung down through a large angle
  CHECK(agree < 1e-8);
  CHECK(closed <= 1e-10);
  CHECK(kin < 1e-10);
  CHECK(energy < 1e-6 * 9.81 * 4.0);
}
