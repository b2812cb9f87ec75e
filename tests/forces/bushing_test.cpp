// The 6-dof bushing: for a small displacement its wrench on B, in F at G's origin, is -K delta;
// the wrenches on the two bodies are equal and opposite; the energy balance closes with large
// rotations and damping; a body on a bushing oscillates at sqrt(k/m) and sqrt(k_rot/I).
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "dynamics/rotation.hpp"
#include "force_rig.hpp"
#include "forces/bushing.hpp"

using namespace yardsim;
using namespace yardsim::forces;
using namespace yardsim::forces::testing;
using dynamics::Matrix3;
using dynamics::Matrix6;
using dynamics::Transform;
using dynamics::Vector6;

namespace {
dynamics::Model twoFreeBodies() {
  dynamics::ModelBuilder b;
  b.setGravity(Vector3::Zero());
  b.addBody("a", "world", dynamics::Joint::free(), dynamics::Transform::identity(),
            dynamics::boxInertia(300.0, Vector3(2, 1, 1)));
  b.addBody("b", "world", dynamics::Joint::free(), dynamics::Transform::identity(),
            dynamics::boxInertia(500.0, Vector3(1, 3, 2)));
  return b.build();
}
// a symmetric positive definite 6x6 with couplings: scale (I + 0.3 (M + M^T)/2)^2-ish
Matrix6 spd(double scale, unsigned seed) {
  std::srand(seed);
  Matrix6 m = Matrix6::Random();
  return scale * (Matrix6::Identity() * 3.0 + 0.2 * (m + m.transpose()));
}
// (free-joint q of one body, X_WB) => q written at offset
void setPose(Eigen::VectorXd& q, int at, const Transform& X) {
  q.segment<3>(at) = X.p;
  dynamics::matrixToQuaternion(X.R, q.data() + at + 3);
}
}  // namespace

TEST_CASE("a small displacement: the wrench on B, in F at G's origin, is -K delta") {
  const dynamics::Model model = twoFreeBodies();
  BushingProperties p;
  p.stiffness = spd(1e5, 7);
  const Transform X_AF{dynamics::axisRotation(Vector3(1, 2, 3).normalized(), 0.7),
                       Vector3(0.5, 0.1, -0.2)};
  const Transform X_BG{dynamics::axisRotation(Vector3(-1, 0, 2).normalized(), -0.4),
                       Vector3(-0.3, 0.2, 0.4)};
  Bushing bushing("b", model, 1, X_AF, 2, X_BG, p);
  const Transform X_WA{dynamics::axisRotation(Vector3(0, 1, 1).normalized(), 0.9),
                       Vector3(1, 2, 3)};
  for (double eps : {1e-3, 1e-5, 0.0}) {
    // (delta = eps [theta; d] in F) => X_WB = X_WA X_AF X_FG X_BG^-1
    Vector6 delta;
    delta << 0.3, -0.5, 0.8, 0.2, 0.7, -0.4;
    if (eps == 0.0) delta.head<3>().setZero();  // pure translation: exact
    delta *= eps == 0.0 ? 1e-2 : eps;
    const Transform X_FG{dynamics::expSO3(delta.head<3>()), delta.tail<3>()};
    const Transform X_WB = X_WA * X_AF * X_FG * X_BG.inverse();
    Rig r(model, {&bushing});
    setPose(r.q, 0, X_WA);
    setPose(r.q, 7, X_WB);
    const Stage s = r.stage();
    CHECK((bushing.state(s).displacement - delta).norm() < 1e-12);
    dynamics::ExternalForces f(model);
    Eigen::VectorXd tau = Eigen::VectorXd::Zero(model.nv);
    bushing.evaluate(s, f, tau);
    // (world wrench about the origin) => in F about G's origin
    const Transform X_WF = X_WA * X_AF;
    const Transform X_WGat{X_WF.R, (X_WB * X_BG).p};
    const dynamics::Force F = X_WGat.invActForce(f.worldFrame(2));
    const Vector6 expected = -(p.stiffness * delta);
    const double rel = (F - expected).norm() / expected.norm();
    // the rotation's effect is of first order in its size: exact without rotation
    CHECK(rel < (eps == 0.0 ? 1e-12 : 2.0 * eps));
    CHECK((f.worldFrame(1) + f.worldFrame(2)).norm() < 1e-12 * f.worldFrame(2).norm());
  }
}

TEST_CASE("energy balance of two tumbling bodies on a bushing with large rotations and damping") {
  const dynamics::Model model = twoFreeBodies();
  BushingProperties p;
  p.stiffness = spd(2e3, 3);
  p.damping = spd(20.0, 5);
  const Transform X_AF{dynamics::axisRotation(Vector3(1, 2, 3).normalized(), 0.7),
                       Vector3(0.5, 0.1, -0.2)};
  const Transform X_BG{dynamics::axisRotation(Vector3(-1, 0, 2).normalized(), -0.4),
                       Vector3(-0.3, 0.2, 0.4)};
  Bushing bushing("b", model, 1, X_AF, 2, X_BG, p);
  Rig r(model, {&bushing});
  r.q << 0, 0, 0, 1, 0, 0, 0, 0.8, 0.3, -0.1, std::cos(0.6), std::sin(0.6), 0, 0;
  r.v << 1.4, -0.2, 0.3, -0.5, 0.1, -0.4, -0.3, 2.2, 0.6, 0.2, 0.6, 0.3;
  double maxAngle = 0.0;
  Rig scan(model, {&bushing});
  scan.q = r.q;
  scan.v = r.v;
  for (int i = 0; i < 2000; ++i) {
    scan.step(1e-3);
    maxAngle = std::max(maxAngle, bushing.state(scan.stage()).displacement.head<3>().norm());
  }
  CHECK(maxAngle > 1.0);  // large relative rotations, rad
  const Rig::Balance b = r.energyBalance(1e-3, 2000);
  CHECK(b.maxWork > 10.0);
  CHECK(b.maxError < 1e-6 * b.maxWork);
}

TEST_CASE("a block on a bushing to the world: heave at sqrt(k/m), roll at sqrt(k_rot/I)") {
  dynamics::ModelBuilder b;
  b.setGravity(Vector3::Zero());
  const dynamics::SpatialInertia I = dynamics::boxInertia(400.0, Vector3(2, 1, 1));
  b.addBody("block", "world", dynamics::Joint::free(), dynamics::Transform::identity(), I);
  const dynamics::Model model = b.build();
  BushingProperties p;
  p.stiffness.diagonal() << 3e3, 3e3, 3e3, 1e4, 1e4, 1e4;
  Bushing bushing("b", model, 0, Transform::identity(), 1, Transform::identity(), p);
  Rig r(model, {&bushing});
  const double z0 = 0.01, a0 = 0.01;
  r.q << 0, 0, z0, std::cos(a0 / 2), std::sin(a0 / 2), 0, 0;  // heave and roll
  const double wz = std::sqrt(1e4 / 400.0), wr = std::sqrt(3e3 / I.inertiaCom(0, 0));
  const double h = 1e-3;
  for (int i = 0; i < 2000; ++i) r.step(h);
  CHECK(r.q[2] == Approx(z0 * std::cos(wz * r.t)).margin(1e-8));
  const Vector3 rpy = dynamics::eulerAngles(dynamics::quaternionToMatrix(r.q.data() + 3));
  CHECK(rpy.x() == Approx(a0 * std::cos(wr * r.t)).margin(1e-6 * a0 + a0 * a0 * 1e-2));
}

TEST_CASE("a bushing refuses a non-symmetric stiffness and an indefinite damping") {
  const dynamics::Model model = twoFreeBodies();
  BushingProperties p;
  p.stiffness = Matrix6::Identity();
  p.stiffness(0, 4) = 1.0;
  CHECK_THROWS_AS(Bushing("b", model, 1, Transform::identity(), 2, Transform::identity(), p),
                  std::invalid_argument);
  p.stiffness = Matrix6::Identity();
  p.damping = -Matrix6::Identity();
  CHECK_THROWS_AS(Bushing("b", model, 1, Transform::identity(), 2, Transform::identity(), p),
                  std::invalid_argument);
  p.damping.setZero();
  CHECK_THROWS_AS(Bushing("b", model, 3, Transform::identity(), 2, Transform::identity(), p),
                  std::invalid_argument);
}
