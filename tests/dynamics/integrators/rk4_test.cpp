// RK4 on analytic cases: pendulum period (small angle and the exact large-amplitude period),
// prismatic slider under gravity, free-body momentum, torque-free rigid body with the
// Dzhanibekov flip, fourth-order convergence with quaternion joints, and the double pendulum's
// energy drift.
#include <catch2/catch.hpp>

#include "dynamics/configuration.hpp"
#include "dynamics/energy.hpp"
#include "dynamics/integrators/rk4.hpp"
#include "dynamics/multibody_system.hpp"
#include "../test_models.hpp"

using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;

namespace {

Model simplePendulum(double l) {
  ModelBuilder b;
  b.addBody("bob", "world", Joint::revolute(Vector3::UnitY()), {},
            makeInertia(1.0, Vector3(0, 0, -l), 1e-12 * Matrix3::Identity()));
  return b.build();
}

// (q0, l) => period by timing two upward zero crossings, located by cubic Hermite interpolation
double measurePeriod(const Model& m, double amplitude, double h) {
  MultibodySystem sys(m);
  Rk4 rk(m);
  Eigen::VectorXd q(1), v(1);
  q << amplitude;
  v << 0.0;
  double t = 0.0;
  std::vector<double> crossings;
  while (crossings.size() < 3) {
    const double q0 = q[0], v0 = v[0], t0 = t;
    Eigen::VectorXd a(1);
    sys.acceleration(t, q, v, a);
    rk.step(sys, t, q, v, h);
    if (q0 < 0.0 && q[0] >= 0.0) {
      // Hermite cubic on [t0, t]; Newton from the linear guess
      const double q1 = q[0], v1 = v[0];
      double s = q0 / (q0 - q1);
      for (int it = 0; it < 20; ++it) {
        const double h00 = 2 * s * s * s - 3 * s * s + 1, h10 = s * s * s - 2 * s * s + s, h01 = -2 * s * s * s + 3 * s * s,
                     h11 = s * s * s - s * s;
        const double f = h00 * q0 + h10 * h * v0 + h01 * q1 + h11 * h * v1;
        const double df = (6 * s * s - 6 * s) * q0 + (3 * s * s - 4 * s + 1) * h * v0 + (-6 * s * s + 6 * s) * q1 +
                          (3 * s * s - 2 * s) * h * v1;
        s -= f / df;
      }
      crossings.push_back(t0 + s * h);
    }
  }
  return crossings[2] - crossings[1];
}

double agm(double a, double b) {
  for (int i = 0; i < 40; ++i) {
    const double an = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = an;
  }
  return a;
}

}  // namespace

TEST_CASE("simple pendulum: small-angle period 2 pi sqrt(l/g), large-amplitude period by the AGM") {
  const double l = 2.0, g = 9.81;
  const Model m = simplePendulum(l);
  const double T0 = 2 * M_PI * std::sqrt(l / g);
  // small angle: the finite-amplitude correction is theta0^2/16 = 6e-8
  CHECK(measurePeriod(m, 1e-3, 1e-3) == Approx(T0).epsilon(1e-7));
  // exact period T = T0 / AGM(1, cos(theta0 / 2)) for any amplitude
  const double th0 = 2.0;
  CHECK(measurePeriod(m, th0, 1e-3) == Approx(T0 / agm(1.0, std::cos(th0 / 2))).epsilon(1e-9));
}

TEST_CASE("prismatic slider on an incline under gravity: s = 1/2 g sin(alpha) t^2") {
  const double alpha = 0.3;
  ModelBuilder b;
  const Vector3 down_slope(std::cos(alpha), 0.0, -std::sin(alpha));
  b.addBody("sled", "world", Joint::prismatic(down_slope), {}, boxInertia(5.0, Vector3(1, 1, 1)));
  const Model m = b.build();
  MultibodySystem sys(m);
  Rk4 rk(m);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(1), v = Eigen::VectorXd::Zero(1);
  double t = 0.0;
  for (int k = 0; k < 200; ++k) rk.step(sys, t, q, v, 0.01);
  CHECK(q[0] == Approx(0.5 * 9.81 * std::sin(alpha) * t * t).epsilon(1e-12));
  CHECK(v[0] == Approx(9.81 * std::sin(alpha) * t).epsilon(1e-12));
}

TEST_CASE("free body without forces keeps its momentum and energy — under gravity its centre follows a parabola") {
  std::mt19937 rng(22);
  ModelBuilder b;
  b.addBody("block", "world", Joint::free(), {}, randomInertia(rng));
  Model m = b.build();
  m.gravity.setZero();
  Data d(m);
  MultibodySystem sys(m);
  Rk4 rk(m);
  Eigen::VectorXd q = randomConfiguration(m, rng), v = randomVectorX(rng, 6, 2.0);
  const Force h0 = momentum(m, d, q, v);
  const double T0 = kineticEnergy(m, d, q, v);
  const Vector3 c0 = centerOfMass(m, d, q);
  double t = 0.0;
  for (int k = 0; k < 2000 / kScale; ++k) rk.step(sys, t, q, v, 1e-3);
  const Force h1 = momentum(m, d, q, v);
  CHECK((h1 - h0).norm() < 1e-9 * h0.norm());
  CHECK(kineticEnergy(m, d, q, v) == Approx(T0).epsilon(1e-9));
  // the centre of mass moves uniformly
  CHECK((centerOfMass(m, d, q) - (c0 + t * h0.tail<3>() / m.totalMass())).norm() < 1e-9);

  Model mg = m;
  mg.gravity = Vector3(0, 0, -9.81);
  MultibodySystem sysg(mg);
  Rk4 rkg(mg);
  Eigen::VectorXd qg = randomConfiguration(mg, rng), vg = randomVectorX(rng, 6, 2.0);
  Data dg(mg);
  const Vector3 cg0 = centerOfMass(mg, dg, qg);
  const Vector3 pg0 = momentum(mg, dg, qg, vg).tail<3>() / mg.totalMass();
  double tg = 0.0;
  for (int k = 0; k < 1000 / kScale; ++k) rkg.step(sysg, tg, qg, vg, 1e-3);
  CHECK((centerOfMass(mg, dg, qg) - (cg0 + pg0 * tg + 0.5 * mg.gravity * tg * tg)).norm() < 1e-9);
}

TEST_CASE("torque-free asymmetric body: angular momentum conserved, intermediate axis flips (Dzhanibekov)") {
  ModelBuilder b;
  b.addBody("wingnut", "world", Joint::free(), {}, makeInertia(1.0, Vector3::Zero(), Vector3(1.0, 2.0, 3.0).asDiagonal()));
  Model m = b.build();
  m.gravity.setZero();
  Data d(m);
  auto run = [&](const Vector3& w0, int axis, double& minAlign, double& maxAlign, double& hErr) {
    MultibodySystem sys(m);
    Rk4 rk(m);
    Eigen::VectorXd q = neutralConfiguration(m), v = Eigen::VectorXd::Zero(6);
    v.head<3>() = w0;
    const Force h0 = momentum(m, d, q, v);
    const Vector3 L = h0.head<3>().normalized();
    double t = 0.0;
    minAlign = 1.0;
    maxAlign = -1.0;
    hErr = 0.0;
    for (int k = 0; k < 8000; ++k) {
      rk.step(sys, t, q, v, 1e-3);
      const double align = (quaternionToMatrix(q.data() + 3).col(axis)).dot(L);
      minAlign = std::min(minAlign, align);
      maxAlign = std::max(maxAlign, align);
      if (k % 100 == 0) hErr = std::max(hErr, (momentum(m, d, q, v) - h0).norm() / h0.norm());
    }
  };
  double lo = 0, hi = 0, err = 0;
  // spin about the intermediate axis (y, I = 2) with a tiny perturbation: the axis turns over
  run(Vector3(1e-3, 5.0, 1e-3), 1, lo, hi, err);
  CHECK(lo < -0.99);  // flipped: the y axis points against the angular momentum
  CHECK(hi > 0.99);   // and back
  CHECK(err < 1e-8);
  // spin about the major axis (z, I = 3) is stable
  run(Vector3(1e-3, 1e-3, 5.0), 2, lo, hi, err);
  CHECK(lo > 0.999);
  CHECK(err < 1e-8);
}

TEST_CASE("RK4 converges with order 4 on a tree with quaternion joints") {
  std::mt19937 rng(23);
  const Model m = randomTree(rng, 5);
  const Eigen::VectorXd q0 = randomConfiguration(m, rng), v0 = randomVectorX(rng, m.nv);
  auto solve = [&](int steps, Eigen::VectorXd& q, Eigen::VectorXd& v) {
    MultibodySystem sys(m);
    Rk4 rk(m);
    q = q0;
    v = v0;
    double t = 0.0;
    for (int k = 0; k < steps; ++k) rk.step(sys, t, q, v, 0.2 / steps);
  };
  Eigen::VectorXd qr, vr, q1, v1, q2, v2, d1(m.nv), d2(m.nv);
  solve(1600, qr, vr);
  solve(25, q1, v1);
  solve(50, q2, v2);
  difference(m, qr, q1, d1);
  difference(m, qr, q2, d2);
  const double e1 = d1.norm() + (v1 - vr).norm(), e2 = d2.norm() + (v2 - vr).norm();
  INFO("errors " << e1 << " " << e2);
  CHECK(e1 / e2 > 12.0);  // 16 for order 4
  CHECK(e1 / e2 < 20.0);
}

TEST_CASE("double pendulum released horizontally: RK4 energy drift below 1e-8 over 10 s") {
  const Model m = planarChain(2);
  Data d(m);
  MultibodySystem sys(m);
  Rk4 rk(m);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(2), v = Eigen::VectorXd::Zero(2);
  // energy measured from the hanging rest state, so that the relative drift is well defined
  Eigen::VectorXd hanging(2);
  hanging << M_PI / 2, 0.0;
  const double Emin = potentialEnergy(m, d, hanging);
  const double E0 = potentialEnergy(m, d, q) - Emin;
  double t = 0.0, drift = 0.0;
  const double h = 1e-3;
  while (t < 10.0 - 0.5 * h) {
    rk.step(sys, t, q, v, h);
    const double E = kineticEnergy(m, d, q, v) + potentialEnergy(m, d, q) - Emin;
    drift = std::max(drift, std::abs(E - E0) / E0);
  }
  INFO("drift " << drift);
  CHECK(drift < 1e-8);
}

TEST_CASE("a random tree with every joint type conserves its energy (bias forces are physical)") {
  std::mt19937 rng(33);
  const Model m = randomTree(rng, 9);
  Data d(m);
  MultibodySystem sys(m);
  Rk4 rk(m);
  Eigen::VectorXd q = randomConfiguration(m, rng), v = randomVectorX(rng, m.nv);
  const double E0 = kineticEnergy(m, d, q, v) + potentialEnergy(m, d, q);
  const double T0 = kineticEnergy(m, d, q, v);
  double t = 0.0, err = 0.0;
  for (int k = 0; k < 2000 / kScale; ++k) {
    rk.step(sys, t, q, v, 1e-4);
    err = std::max(err, std::abs(kineticEnergy(m, d, q, v) + potentialEnergy(m, d, q) - E0));
  }
  INFO("energy error " << err << " of kinetic energy " << T0);
  CHECK(err < 1e-9 * std::max(1.0, T0));
}
