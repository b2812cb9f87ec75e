// A lumped-mass line under a winch (forces/lines/lumped_line.cpp, a crane rope with mass): at a
// time t its forces and node masses are those of the same line built with the winch's length L(t);
// the damping acts on the elongation beyond what the winch pays out (a rope hauled in at rest in
// its own stretch feels only EA e); dV/dt at fixed positions, the winch's power, equals the central
// difference of the energy in time; the force Jacobian equals central differences while the winch
// runs; a winch that does not start at the line's length, or may haul in to nothing, is refused.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <vector>

#include "forces/lines/lumped_line.hpp"

using namespace yardsim;
using namespace yardsim::forces;
using dynamics::Matrix3;
using dynamics::Vector3;

namespace {

// a 20 m wire rope in air: 10 kg/m, 40 mm, EA 5e7 N, 8 segments, half its segments' critical
// damping, bending stiffness 2e4 N m^2
LumpedLineProperties wire() {
  LumpedLineProperties p;
  p.length = 20.0;
  p.segments = 8;
  p.diameter = 0.04;
  p.massPerLength = 10.0;
  p.ea = 5e7;
  p.ei = 2e4;
  p.damping = -0.5;
  p.waterDensity = 1.225;
  return p;
}

// (a winch at 20 m) => hauling in at 0.4 m/s from t = 1 s: L(3) = 19.2 m, L'(3) = -0.4 m/s
std::shared_ptr<Winch> hauling() {
  auto w = std::make_shared<Winch>(20.0, 0.01);
  w->setPayoutRate(1.0, -0.4);
  return w;
}

// (segments, stretched by e, per node a bend) => nodes along a wavy line from the origin, with
// segment lengths l (1 + e)
Eigen::Matrix3Xd wavy(int n, double l, double e) {
  Eigen::Matrix3Xd r(3, n + 1);
  r.col(0).setZero();
  for (int i = 0; i < n; ++i)
    r.col(i + 1) =
        r.col(i) + l * (1.0 + e) * Vector3(1.0, 0.1 * std::sin(i), -0.3 + 0.05 * i).normalized();
  return r;
}

}  // namespace

TEST_CASE("lumped line under a winch: its forces at t are those of a line of length L(t)") {
  const auto winch = hauling();
  const LumpedLine line(wire(), "hoist", nullptr, nullptr, winch);
  LumpedLineProperties shorter = wire();
  shorter.length = 19.2;
  shorter.damping = line.dampingCoefficient();  // (the damping in N s stays the start's)
  const LumpedLine fixed(shorter, "fixed");
  REQUIRE(line.segmentLength(3.0) == Approx(2.4).epsilon(1e-15));
  REQUIRE(line.segmentLengthRate(3.0) == Approx(-0.05).epsilon(1e-15));
  // (at rest: v = 0; the winch's rate enters only through the damping, so pay in nothing there:
  // compare at t = 0.5, before it starts, against the 20 m line, and at t = 3 without damping)
  const Eigen::Matrix3Xd r = wavy(8, 2.4, 0.003);
  const Eigen::Matrix3Xd v = Eigen::Matrix3Xd::Zero(3, 9);
  Eigen::Matrix3Xd f(3, 9), g(3, 9), fc(3, 9), gc(3, 9);
  Eigen::VectorXd t1(8), t2(8);
  LumpedLineProperties undamped = wire();
  undamped.damping = 0.0;
  const LumpedLine still(undamped, "hoist", nullptr, nullptr, winch);
  undamped.length = 19.2;
  const LumpedLine stillFixed(undamped, "fixed");
  still.nodeForces(r, v, 3.0, f, t1);
  stillFixed.nodeForces(r, v, 3.0, g, t2);
  CHECK((f - g).norm() <= 1e-12 * g.norm());
  CHECK(t1.minCoeff() > 0.0);  // every segment taut: the strains are compared
  // (conservative forces and energy) => the same as the shorter line's, with damping too
  line.conservativeForces(r, 3.0, fc);
  fixed.conservativeForces(r, 0.0, gc);
  CHECK((fc - gc).norm() <= 1e-12 * gc.norm());
  CHECK(line.potentialEnergy(r, 3.0) == Approx(fixed.potentialEnergy(r, 0.0)).epsilon(1e-13));
  // (before the winch starts) => the 20 m line's
  const LumpedLine start(wire(), "start");
  line.nodeForces(r, v, 0.5, f, t1);
  start.nodeForces(r, v, 0.5, g, t2);
  CHECK((f - g).norm() <= 1e-12 * g.norm());
}

TEST_CASE("lumped line under a winch: its node masses at t are those of a line of length L(t)") {
  // (hauling in, added mass on) => every node's 3x3 mass at t = 3 (L = 19.2 m), the ends' half
  // segments included, equals the 19.2 m line's; before the winch starts, the 20 m line's
  LumpedLineProperties p = wire();
  p.waterDensity = 1025.0;
  p.can = 1.0;
  p.cat = 0.3;
  const LumpedLine line(p, "hoist", nullptr, nullptr, hauling());
  LumpedLineProperties shorter = p;
  shorter.length = 19.2;
  const LumpedLine fixed(shorter, "fixed"), start(p, "start");
  const Eigen::Matrix3Xd r = wavy(8, 2.4, 0.003);
  std::vector<Matrix3> m(9), expected(9);
  line.nodeMass(r, 3.0, m);
  fixed.nodeMass(r, 0.0, expected);
  for (int i = 0; i <= 8; ++i) {
    INFO("node " << i);
    CHECK((m[static_cast<std::size_t>(i)] - expected[static_cast<std::size_t>(i)]).norm() <=
          1e-14 * expected[static_cast<std::size_t>(i)].norm());
  }
  // (an inner node: 2.4 m of rope, 24 kg of wire and the water's; an end: half of it) => the
  // trace 3 mu l + rho A l (2 Can + Cat)
  const double l = 2.4, area = 0.25 * 3.141592653589793 * 0.04 * 0.04;
  CHECK(m[4].trace() == Approx(3.0 * 10.0 * l + 1025.0 * area * l * 2.3).epsilon(1e-12));
  CHECK(m[0].trace() == Approx(0.5 * m[4].trace()).epsilon(1e-12));
  line.nodeMass(r, 0.5, m);
  start.nodeMass(r, 0.0, expected);
  CHECK((m[4] - expected[4]).norm() <= 1e-14 * expected[4].norm());
  CHECK(m[4].trace() > expected[0].trace());
}

TEST_CASE("lumped line under a winch: the damping acts on the elongation beyond the payout") {
  // (a straight rope at strain e whose nodes move as the winch hauls it in, v_i = i l' (1 + e)
  // along it: its strain does not change) => every tension is EA e, the damping adds nothing;
  // nodes at rest instead see the winch's strain rate -l'/l (1 + e) through the damping
  const auto winch = hauling();
  const LumpedLine line(wire(), "hoist", nullptr, nullptr, winch);
  const double t = 3.0, l = line.segmentLength(t), lr = line.segmentLengthRate(t), e = 0.002;
  Eigen::Matrix3Xd r(3, 9), v(3, 9), f(3, 9);
  const Vector3 u = Vector3(0.6, 0.0, -0.8);
  for (int i = 0; i <= 8; ++i) {
    r.col(i) = i * l * (1.0 + e) * u;
    v.col(i) = i * lr * (1.0 + e) * u;
  }
  Eigen::VectorXd tension(8);
  line.nodeForces(r, v, t, f, tension);
  for (int i = 0; i < 8; ++i) CHECK(tension[i] == Approx(5e7 * e).epsilon(1e-9));
  v.setZero();
  line.nodeForces(r, v, t, f, tension);
  const double c = line.dampingCoefficient();
  REQUIRE(c > 1e3);
  CHECK(tension[3] == Approx(5e7 * e - c * lr / l * (1.0 + e)).epsilon(1e-9));
}

TEST_CASE("lumped line under a winch: dV/dt at fixed positions is the winch's power") {
  // (energy V(r, t) with L(t)) => potentialEnergyRate against its central difference in t, for
  // strained, bent and slack segments; zero while the winch stands
  const auto winch = hauling();
  const LumpedLine line(wire(), "hoist", nullptr, nullptr, winch);
  Eigen::Matrix3Xd r = wavy(8, 2.4, 0.004);
  r.col(8) = r.col(7) + 0.9 * (r.col(8) - r.col(7));  // the last segment slack
  const double h = 1e-4, t = 3.0;
  const double central =
      (line.potentialEnergy(r, t + h) - line.potentialEnergy(r, t - h)) / (2 * h);
  INFO("dV/dt " << line.potentialEnergyRate(r, t) << " W against " << central << " W");
  CHECK(std::abs(central) > 1e3);
  CHECK(line.potentialEnergyRate(r, t) == Approx(central).epsilon(1e-6));
  CHECK(line.potentialEnergyRate(r, 0.5) == 0.0);
}

TEST_CASE("lumped line under a winch: the force Jacobian equals central differences") {
  // (hauling in, nodes moving, taut and bent) => df/dr and df/dv, with the winch's damping term
  const auto winch = hauling();
  const LumpedLine line(wire(), "hoist", nullptr, nullptr, winch);
  const double t = 3.0;
  const Eigen::Matrix3Xd r = wavy(8, 2.4, 0.004);
  Eigen::Matrix3Xd v(3, 9);
  for (int i = 0; i <= 8; ++i) v.col(i) = Vector3(0.02 * i, -0.01 * i, -0.03 * (i % 3));
  const int b = line.jacobianBandwidth(), w = 2 * b + 1;
  std::vector<Matrix3> dfdr(static_cast<std::size_t>(w * 9)), dfdv(dfdr.size());
  line.forceJacobian(r, v, t, dfdr, dfdv);
  Eigen::Matrix3Xd fp(3, 9), fm(3, 9);
  Eigen::VectorXd tension(8);
  double worst = 0.0, scale = 0.0;
  for (int which = 0; which < 2; ++which)
    for (int j = 0; j <= 8; ++j)
      for (int k = 0; k < 3; ++k) {
        const double h = which == 0 ? 1e-7 : 1e-5;
        Eigen::Matrix3Xd rp = r, rm = r, vp = v, vm = v;
        (which == 0 ? rp : vp)(k, j) += h;
        (which == 0 ? rm : vm)(k, j) -= h;
        line.nodeForces(rp, vp, t, fp, tension);
        line.nodeForces(rm, vm, t, fm, tension);
        for (int i = std::max(0, j - b); i <= std::min(8, j + b); ++i) {
          const Vector3 c = (fp.col(i) - fm.col(i)) / (2 * h);
          const Matrix3& a =
              (which == 0 ? dfdr : dfdv)[static_cast<std::size_t>(w * i + j - i + b)];
          worst = std::max(worst, (a.col(k) - c).norm());
          scale = std::max(scale, c.norm());
        }
      }
  INFO("largest difference " << worst << " of " << scale);
  CHECK(scale > 1e7);
  CHECK(worst <= 1e-6 * scale);
}

TEST_CASE("lumped line under a winch: a winch that does not start at the line's length") {
  CHECK_THROWS_AS(
      LumpedLine(wire(), "hoist", nullptr, nullptr, std::make_shared<Winch>(21.0, 0.01)),
      std::invalid_argument);
  // (a winch that may haul in to nothing) => refused: the nodes' masses follow the length
  CHECK_THROWS_AS(LumpedLine(wire(), "hoist", nullptr, nullptr, std::make_shared<Winch>(20.0, 0.0)),
                  std::invalid_argument);
}
