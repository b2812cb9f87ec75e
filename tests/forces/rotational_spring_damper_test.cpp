// The joint spring-damper: a wheel on a revolute joint oscillates at sqrt(k/I) and decays as the
// closed form, a preload shifts its rest angle by -preload/k, a slide on a prismatic joint, the
// energy balance with a table and damping, and refused joints.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "force_rig.hpp"
#include "forces/rotational_spring_damper.hpp"

using namespace yardsim;
using namespace yardsim::forces;
using namespace yardsim::forces::testing;

namespace {
// a wheel on a revolute joint about z; its inertia about z, kg m^2
dynamics::Model wheel(double& izz) {
  dynamics::ModelBuilder b;
  b.setGravity(Vector3::Zero());
  const dynamics::SpatialInertia I = dynamics::boxInertia(200.0, Vector3(1.0, 0.6, 0.2));
  izz = I.inertiaCom(2, 2);
  b.addBody("wheel", "world", dynamics::Joint::revolute(Vector3::UnitZ()),
            dynamics::Transform::identity(), I);
  return b.build();
}
}  // namespace

TEST_CASE("a wheel on a torsion spring: period 2 pi sqrt(I/k), damped decay, preload") {
  double izz = 0.0;
  const dynamics::Model model = wheel(izz);
  const double k = 500.0, w = std::sqrt(k / izz), x0 = 0.4;
  for (double zeta : {0.0, 0.1}) {
    JointSpringProperties p;
    p.neutral = 0.2;
    p.curve = SpringCurve::linear(k);
    p.damping = zeta * 2.0 * std::sqrt(k * izz);
    RotationalSpringDamper spring("s", model, 1, 0, p);
    Rig r(model, {&spring});
    r.q[0] = 0.2 + x0;
    const double h = 2.0 * std::numbers::pi / w / 400.0, wd = w * std::sqrt(1.0 - zeta * zeta);
    double maxErr = 0.0;
    for (int i = 0; i < 800; ++i) {
      r.step(h);
      const double x =
          x0 * std::exp(-zeta * w * r.t) *
          (std::cos(wd * r.t) + zeta / std::sqrt(1.0 - zeta * zeta) * std::sin(wd * r.t));
      maxErr = std::max(maxErr, std::abs(r.q[0] - 0.2 - x));
    }
    CHECK(maxErr < 1e-7 * x0);
  }
  // (preload 50 N m) => no torque at q0 - 50/k, a restoring torque -k dx around it
  JointSpringProperties p;
  p.neutral = 0.2;
  p.curve = SpringCurve::linear(k);
  p.preload = 50.0;
  RotationalSpringDamper spring("s", model, 1, 0, p);
  Rig r(model, {&spring});
  r.q[0] = 0.2 - 50.0 / k;
  CHECK(std::abs(spring.generalizedForce(r.stage())) < 1e-12);
  r.q[0] += 0.01;
  CHECK(spring.generalizedForce(r.stage()) == Approx(-k * 0.01));
}

TEST_CASE("a slide on a prismatic joint: energy balance, linear and with a table") {
  const dynamics::Model model = verticalBlock(800.0);
  JointSpringProperties p;
  p.neutral = 1.0;
  p.damping = 150.0;
  p.preload = 300.0;
  // (h, curve) => the balance over 4 s from q = 1.5 m, v = 1 m/s
  const auto run = [&](double h, const SpringCurve& c) {
    p.curve = c;
    RotationalSpringDamper spring("s", model, 1, 0, p);
    Rig r(model, {&spring});
    r.q[0] = 1.5;
    r.v[0] = 1.0;
    const Rig::Balance b = r.energyBalance(h, static_cast<int>(std::lround(4.0 / h)));
    CHECK(spring.power(r.stage()) <= 0.0);
    return b;
  };
  const Rig::Balance lin = run(1e-3, SpringCurve::linear(1e4));
  CHECK(lin.maxWork > 10.0);
  CHECK(lin.maxError < 1e-9 * lin.maxWork);
  // a table: its kinks cut RK4's order, but the balance still converges with the step
  const SpringCurve table = SpringCurve::table({-0.5, 0.0, 0.3, 0.6}, {-2e4, 0.0, 3e3, 1.5e4});
  const Rig::Balance coarse = run(1e-3, table), fine = run(2.5e-4, table);
  CHECK(fine.maxError < coarse.maxError / 16.0);
  CHECK(fine.maxError < 1e-6 * fine.maxWork);
}

TEST_CASE("a joint spring refuses a free joint, a coordinate outside the joint, negative damping") {
  dynamics::ModelBuilder b;
  b.addBody("free", "world", dynamics::Joint::free(), dynamics::Transform::identity(),
            dynamics::boxInertia(1.0, Vector3(1, 1, 1)));
  const dynamics::Model free = b.build();
  JointSpringProperties p;
  CHECK_THROWS_AS(RotationalSpringDamper("s", free, 1, 0, p), std::invalid_argument);
  double izz = 0.0;
  const dynamics::Model model = wheel(izz);
  CHECK_THROWS_AS(RotationalSpringDamper("s", model, 1, 1, p), std::invalid_argument);
  CHECK_THROWS_AS(RotationalSpringDamper("s", model, 2, 0, p), std::invalid_argument);
  p.damping = -1.0;
  CHECK_THROWS_AS(RotationalSpringDamper("s", model, 1, 0, p), std::invalid_argument);
}
