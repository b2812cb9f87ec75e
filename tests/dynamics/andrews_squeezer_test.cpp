// Andrews' squeezing mechanism (Hairer & Wanner, Solving ODEs II, sec. VII.7; the "andrews"
// problem of the Bari test set for IVP solvers): seven planar bodies, one loop system closed at a
// single point by three revolute cuts, a stiff spring (c0 = 4530 N/m) and a driving torque. The
// reference positions (and velocities) at t = 0.03 s are the published ones; we require six
// significant digits.
#include <catch2/catch.hpp>

#include "dynamics/integrators/rk4.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/loop_constraints.hpp"
#include "dynamics/multibody_system.hpp"
#include "test_models.hpp"

using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;

namespace {
// Hairer & Wanner's data (SI units)
constexpr double m1 = .04325, m2 = .00365, m3 = .02373, m4 = .00706, m5 = .07050, m6 = .00706, m7 = .05498;
constexpr double i1 = 2.194e-6, i2 = 4.410e-7, i3 = 5.255e-6, i4 = 5.667e-7, i5 = 1.169e-5, i6 = 5.667e-7, i7 = 1.912e-5;
constexpr double xa = -.06934, ya = -.00227, xb = -.03635, yb = .03273, xc = .014, yc = .072;
constexpr double d = 28e-3, da = 115e-4, e = 2e-2, ea = 1421e-5, rr = 7e-3, ra = 92e-5;
constexpr double ss = 35e-3, sa = 1874e-5, sb = 1043e-5, sc = 18e-3, sd = 2e-2, ta = 2308e-5, tb = 916e-5;
constexpr double u = 4e-2, ua = 1228e-5, ub = 449e-5, zf = 2e-2, zt = 4e-2, fa = 1421e-5;
constexpr double mom = 0.033, c0 = 4530.0, l0 = 0.07785;

SpatialInertia planarBody(double mass, double x, double y, double izz) {
  return makeInertia(mass, Vector3(x, y, 0.0), izz * Matrix3::Identity());
}

Transform at(double x, double y) { return Transform::translation(Vector3(x, y, 0.0)); }

// Bodies K1..K7 of the book. Angles: beta (K1 about O), Theta (K2 relative to K1), gamma (K3 about B),
// delta (K5 about A), Phi (K4 relative to K5), epsilon (K7 about A), Omega (K6 relative to K7).
// Only distances of centres of mass from fixed pivots enter the book's mass matrix; we place them
// on the local axes with the book's distances.
Model squeezer() {
  ModelBuilder b;
  b.setGravity(Vector3::Zero());
  b.addBody("K1", "world", Joint::revolute(), {}, planarBody(m1, ra, 0, i1));
  b.addBody("K2", "K1", Joint::revolute(), at(rr, 0), planarBody(m2, -da, 0, i2));
  b.addBody("K3", "world", Joint::revolute(), at(xb, yb), planarBody(m3, sa, sb, i3));
  b.addBody("K5", "world", Joint::revolute(), at(xa, ya), planarBody(m5, ta, tb, i5));
  b.addBody("K4", "K5", Joint::revolute(), at(zt, 0), planarBody(m4, 0, -(e - ea), i4));
  b.addBody("K7", "world", Joint::revolute(), at(xa, ya), planarBody(m7, ua, ub, i7));
  b.addBody("K6", "K7", Joint::revolute(), at(0, -u), planarBody(m6, zf - fa, 0, i6));
  // the point P at the end of K2 is pinned to K3, K4 and K6
  b.addLoop("P-K3", "K2", at(-d, 0), "K3", at(0, -ss), kPlanarPointConstraint);
  b.addLoop("P-K4", "K2", at(-d, 0), "K4", at(0, -e), kPlanarPointConstraint);
  b.addLoop("P-K6", "K2", at(-d, 0), "K6", at(zf, 0), kPlanarPointConstraint);
  return b.build();
}

struct Angles {
  int beta, theta, gamma, phi, delta, omega, epsilon;  // indices into q
};
}  // namespace

TEST_CASE("Andrews' squeezing mechanism reproduces Hairer & Wanner's positions at t = 0.03 s") {
  const Model m = squeezer();
  REQUIRE(m.nv == 7);
  REQUIRE(m.nc == 6);
  auto idx = [&](const char* name) { return m.idxQ[m.bodyIndex(name)]; };
  const Angles a{idx("K1"), idx("K2"), idx("K3"), idx("K4"), idx("K5"), idx("K6"), idx("K7")};
  Eigen::VectorXd q(7), v = Eigen::VectorXd::Zero(7);
  q[a.beta] = -0.0617138900142764496358948458001;
  q[a.theta] = 0.0;
  q[a.gamma] = 0.455279819163070380255912382449;
  q[a.phi] = 0.222668390165885884674473185609;
  q[a.delta] = 0.487364979543842550225598953530;
  q[a.omega] = -0.222668390165885884674473185609;
  q[a.epsilon] = 1.23054744454982119249735015568;
  Data data(m);
  REQUIRE(loopResidualNorm(m, data, q) < 1e-15);

  MultibodySystem sys(m);
  const int k1 = m.bodyIndex("K1"), k3 = m.bodyIndex("K3");
  sys.setForces([&](double, const Eigen::VectorXd&, const Eigen::VectorXd&, const Data& dk, ExternalForces& f, Eigen::VectorXd&) {
    // (K3 pose) => spring force from the fixed point C to the point D on K3; torque mom on K1
    const Vector3 D = pointPosition(dk, k3, Vector3(sd, -sc, 0.0));
    const Vector3 dC = D - Vector3(xc, yc, 0.0);
    const double L = dC.norm();
    f.addPointForceWorld(k3, D, -c0 * (L - l0) / L * dC);
    Force torque = Force::Zero();
    torque[2] = mom;
    f.addBodyFrame(k1, torque);
  });
  sys.setProjection(true);
  // the initial accelerations of the book: beta'' = 14222.44..., Theta'' = -10666.83...
  Eigen::VectorXd acc(7);
  sys.acceleration(0.0, q, v, acc);
  CHECK(acc[a.beta] == Approx(14222.4439199541138705911625887).epsilon(1e-10));
  CHECK(acc[a.theta] == Approx(-10666.8329399655854029433719415).epsilon(1e-10));
  for (int k : {a.gamma, a.phi, a.delta, a.omega, a.epsilon}) CHECK(std::abs(acc[k]) < 1e-8);

  Rk4 rk(m);
  double t = 0.0;
  const int steps = 6000;
  for (int k = 0; k < steps; ++k) rk.step(sys, t, q, v, 0.03 / steps);
  CHECK(loopResidualNorm(m, data, q) <= 1e-10);
  const double tol = 5e-7;  // six significant digits
  CHECK(q[a.beta] == Approx(0.1581077119629904e+02).epsilon(tol));
  CHECK(q[a.theta] == Approx(-0.1575637105984298e+02).epsilon(tol));
  CHECK(q[a.gamma] == Approx(0.4082224013073101e-01).epsilon(tol));
  CHECK(q[a.phi] == Approx(-0.5347301163226948e+00).epsilon(tol));
  CHECK(q[a.delta] == Approx(0.5244099658805304e+00).epsilon(tol));
  CHECK(q[a.omega] == Approx(0.5347301163226948e+00).epsilon(tol));
  CHECK(q[a.epsilon] == Approx(0.1048080741042263e+01).epsilon(tol));
  // velocities (the test set's y(8..14)), also to six significant digits
  CHECK(v[a.beta] == Approx(0.1139920302151208e+04).epsilon(tol));
  CHECK(v[a.theta] == Approx(-0.1424379294994111e+04).epsilon(tol));
  CHECK(v[a.gamma] == Approx(0.1103291221937134e+02).epsilon(tol));
  CHECK(v[a.phi] == Approx(0.1929337464421385e+02).epsilon(tol));
  CHECK(v[a.delta] == Approx(0.5735699284790808e+00).epsilon(tol));
  CHECK(v[a.omega] == Approx(-0.1929337464421385e+02).epsilon(tol));
  CHECK(v[a.epsilon] == Approx(0.3231791658026955e+00).epsilon(tol));
}
