// Linear and quadratic damping: the closed-form decay of a free body's velocity, the moment of a
// force applied at an offset point, and the energy balance with its (negative) power.
#include <catch2/catch.hpp>

#include <cmath>

#include "dynamics/energy.hpp"
#include "force_rig.hpp"
#include "forces/linear_quadratic_damping.hpp"

using namespace yardsim;
using namespace yardsim::forces;
using namespace yardsim::forces::testing;

namespace {
dynamics::Model freeBlock(double m) {
  dynamics::ModelBuilder b;
  b.setGravity(Vector3::Zero());
  b.addBody("block", "world", dynamics::Joint::free(), dynamics::Transform::identity(),
            dynamics::boxInertia(m, Vector3(4, 2, 1)));
  return b.build();
}
}  // namespace

TEST_CASE("linear damping decays as e^{-b t/m}, quadratic as 1/(1 + c v0 t/m)") {
  const double m = 1000.0, v0 = 2.0;
  const dynamics::Model model = freeBlock(m);
  DampingCoefficients c;
  c.linear[0] = 300.0;     // surge
  c.quadratic[2] = 150.0;  // heave
  LinearQuadraticDamping damping("d", model, 1, Vector3::Zero(), c);
  Rig r(model, {&damping});
  r.q << 0, 0, 0, 1, 0, 0, 0;
  r.v << 0, 0, 0, v0, 0, v0;  // [omega; v] in the body frame
  for (int i = 0; i < 1000; ++i) r.step(0.005);
  CHECK(r.v[3] == Approx(v0 * std::exp(-300.0 * r.t / m)).epsilon(1e-9));
  CHECK(r.v[5] == Approx(v0 / (1 + 150.0 * v0 * r.t / m)).epsilon(1e-9));
  const std::array<double, 6> l = damping.load(r.stage());
  CHECK(l[0] == Approx(-300.0 * r.v[3]));
  CHECK(l[2] == Approx(-150.0 * r.v[5] * r.v[5]));
}

TEST_CASE("damping at an offset point: its moment, and energy balance with the negative power") {
  const dynamics::Model model = freeBlock(500.0);
  DampingCoefficients c;
  c.linear = {100, 200, 300, 400, 500, 600};
  c.quadratic = {10, 20, 30, 40, 50, 60};
  const Vector3 p(1.0, -0.5, 0.3);
  LinearQuadraticDamping damping("d", model, 1, p, c);
  Rig r(model, {&damping});
  r.q << 1, 2, 3, std::cos(0.2), std::sin(0.2), 0, 0;
  r.v << 0.3, -0.2, 0.5, 1.0, -0.5, 0.2;
  // (a pure yaw rate) => a sway force at the point and its moment p x F about the origin
  {
    Eigen::VectorXd v = Eigen::VectorXd::Zero(6);
    v[2] = 0.1;
    Rig s(model, {&damping});
    s.q = r.q;
    s.v = v;
    const Stage st = s.stage();
    dynamics::ExternalForces f(model);
    Eigen::VectorXd tau = Eigen::VectorXd::Zero(6);
    damping.evaluate(st, f, tau);
    const Vector3 u = Vector3(0, 0, 0.1).cross(p);  // velocity of the point
    const Vector3 F(-(100 * u.x() + 10 * std::abs(u.x()) * u.x()), -(200 * u.y() + 20 * std::abs(u.y()) * u.y()),
                    -(300 * u.z() + 30 * std::abs(u.z()) * u.z()));
    const Vector3 M(0, 0, -(600 * 0.1 + 60 * 0.01));
    CHECK((f.bodyFrame(1).tail<3>() - F).norm() < 1e-12);
    CHECK((f.bodyFrame(1).head<3>() - (M + p.cross(F))).norm() < 1e-12);
    CHECK(damping.power(st) < 0.0);
  }
  const Rig::Balance b = r.energyBalance(0.002, 1000);
  CHECK(b.maxWork > 10.0);
  CHECK(b.maxError < 1e-7 * b.maxWork);
  DampingCoefficients bad;
  bad.linear[4] = -1.0;
  CHECK_THROWS_AS(LinearQuadraticDamping("d", model, 1, p, bad), std::invalid_argument);
}

TEST_CASE("quadratic damping opposes the motion in every direction, with either sign, and only takes energy") {
  // (one dof at a time, +v0 and -v0, the body's own kinetic energy) => the closed form for the
  // velocity (the sign kept), and a kinetic energy that never rises: dissipation checked without
  // the provider's own power
  const double m = 1000.0, c = 150.0, v0 = 2.0;
  const dynamics::Model model = freeBlock(m);
  const Vector3 inertia = model.inertias[1].inertiaCom.diagonal();
  for (std::size_t dof = 0; dof < 6; ++dof)
    for (const double sign : {1.0, -1.0}) {
      INFO("dof " << dof << ", sign " << sign);
      DampingCoefficients coeff;
      coeff.quadratic[dof] = c;
      LinearQuadraticDamping damping("d", model, 1, Vector3::Zero(), coeff);
      Rig r(model, {&damping});
      r.q << 0, 0, 0, 1, 0, 0, 0;
      r.v.setZero();
      // naval order surge, sway, heave, roll, pitch, yaw; body velocity [omega; v]
      const int iv = dof < 3 ? 3 + static_cast<int>(dof) : static_cast<int>(dof) - 3;
      const double mass = dof < 3 ? m : inertia[static_cast<Eigen::Index>(dof - 3)];
      r.v[iv] = sign * v0;
      dynamics::Data d(model);
      double kinetic = dynamics::kineticEnergy(model, d, r.q, r.v);
      for (int i = 0; i < 400; ++i) {
        r.step(0.005);
        const double now = dynamics::kineticEnergy(model, d, r.q, r.v);
        REQUIRE(now <= kinetic * (1 + 1e-12));
        kinetic = now;
      }
      CHECK(r.v[iv] == Approx(sign * v0 / (1 + c * v0 * r.t / mass)).epsilon(1e-8));
    }
}
