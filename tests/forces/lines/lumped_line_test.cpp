// The lumped-mass line: a line relaxed to rest reproduces the quasi-static catenary's fairlead
// force within 1 % at 20 segments and converges with refinement (suspended and touching down),
// released from a shape off its plane it settles to the catenary's; energy is conserved
// without dissipation and only lost with it; tension-only Kelvin-Voigt segments, critical
// damping, Morison drag, fluid inertia and the sea bed against hand formulas.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "forces/lines/catenary.hpp"
#include "forces/lines/lumped_line.hpp"

using namespace yardsim;
using namespace yardsim::forces;
using dynamics::Matrix3;
using dynamics::Vector3;

namespace {

// a 500 m chain: 120 kg/m, d = 0.12 m (w = 1063.5 N/m in water), EA = 7.5e8 N
LumpedLineProperties chain(int segments, bool seabed) {
  LumpedLineProperties p;
  p.length = 500.0;
  p.segments = segments;
  p.diameter = 0.12;
  p.massPerLength = 120.0;
  p.ea = 7.5e8;
  p.damping = -0.5;  // half the critical damping of a segment's axial mode
  p.seabed = seabed;
  p.seabedZ = 0.0;
  p.bedStiffness = 1e7;  // Pa/m: sinks w/(kb d) < 1 mm
  p.bedDamping = 1e4;
  return p;
}

// (line, r: nodes 0 and N held, t) => r relaxed to rest by symplectic Euler with a fictitious
// damping 0.5/s on the node velocities, until the largest net force on a free node is below
// 1e-7 of a node's weight (false if it never gets there)
bool relax(const LumpedLine& line, Eigen::Matrix3Xd& r) {
  const int n = line.nodes();
  Eigen::Matrix3Xd v = Eigen::Matrix3Xd::Zero(3, n), f(3, n);
  Eigen::VectorXd tension(n - 1);
  const LumpedLineProperties& p = line.properties();
  const double l = line.segmentLength();
  const double wMax = 2.0 / l * std::sqrt(p.ea / p.massPerLength);  // highest axial mode, rad/s
  const double dt = 0.3 / wMax, m = p.massPerLength * l;
  for (long k = 0; k < 20000000; ++k) {
    line.nodeForces(r, v, 0.0, f, tension);
    double worst = 0.0;
    for (int i = 1; i + 1 < n; ++i) {
      v.col(i) += dt * (f.col(i) / m - 0.5 * v.col(i));
      r.col(i) += dt * v.col(i);
      worst = std::max(worst, f.col(i).norm());
    }
    if (k > 1000 && worst < 1e-7 * line.weightPerLength() * l) return true;
  }
  return false;
}

// (line, solution, XF, offset of the line out of its plane, m) => nodes at the catenary's
// points of their unstretched arc lengths, pushed sideways by offset sin(pi s/L)
Eigen::Matrix3Xd startShape(const LumpedLine& line, const CatenaryParameters& cp,
                            const CatenarySolution& s, double xf, double offset) {
  Eigen::Matrix3Xd r(3, line.nodes());
  for (int i = 0; i < line.nodes(); ++i) {
    const double arc = i * line.segmentLength();
    const CatenaryPoint pt = catenaryPoint(cp, s, xf, arc);
    r.col(i) = Vector3(pt.x, offset * std::sin(std::numbers::pi * arc / cp.length), pt.z);
  }
  return r;
}

struct Comparison {
  double fairlead = 0.0, anchorH = 0.0, shape = 0.0;
};

// (segments, seabed, XF, ZF) => relative differences of the relaxed lumped line from the
// catenary: fairlead force, anchor horizontal force, largest node distance from the profile / L
Comparison compare(int segments, bool seabed, double xf, double zf, double offset) {
  const LumpedLine line(chain(segments, seabed), "chain");
  const CatenaryParameters cp{500.0, 7.5e8, line.weightPerLength(), seabed, 0.0};
  const CatenarySolution s = solveCatenary(cp, xf, zf);
  REQUIRE(s.status == CatenaryStatus::Converged);
  Eigen::Matrix3Xd r = startShape(line, cp, s, xf, offset);
  REQUIRE(relax(line, r));
  const int n = line.nodes();
  Eigen::Matrix3Xd f(3, n);
  Eigen::VectorXd tension(n - 1);
  line.nodeForces(r, Eigen::Matrix3Xd::Zero(3, n), 0.0, f, tension);
  const Vector3 fB(-s.hf, 0.0, -s.vf);
  Comparison c;
  c.fairlead = (f.col(n - 1) - fB).norm() / fB.norm();
  c.anchorH = std::abs(f(0, 0) - s.ha) / s.hf;
  for (int i = 0; i < n; ++i) {
    const CatenaryPoint pt = catenaryPoint(cp, s, xf, i * line.segmentLength());
    c.shape = std::max(c.shape, (r.col(i) - Vector3(pt.x, 0.0, pt.z)).norm() / cp.length);
  }
  return c;
}

}  // namespace

TEST_CASE("a lumped line at rest reproduces the catenary within 1 % at 20 segments, converging") {
  for (bool seabed : {false, true}) {
    // suspended: B 400 m away and 200 m up, anchor off the bed; touching down: on the bed
    const Comparison c10 = compare(10, seabed, 400.0, 200.0, 0.0);
    const Comparison c20 = compare(20, seabed, 400.0, 200.0, 0.0);
    const Comparison c40 = compare(40, seabed, 400.0, 200.0, 0.0);
    WARN((seabed ? "touching down" : "suspended")
         << ": fairlead force differs by " << c10.fairlead << ", " << c20.fairlead << ", "
         << c40.fairlead << " at 10, 20, 40 segments; anchor " << c10.anchorH << ", " << c20.anchorH
         << ", " << c40.anchorH << "; shape " << c10.shape << ", " << c20.shape << ", "
         << c40.shape);
    CHECK(c20.fairlead < 0.01);
    CHECK(c20.fairlead < 0.5 * c10.fairlead);
    CHECK(c40.fairlead < 0.5 * c20.fairlead);
    CHECK(c40.anchorH < c20.anchorH);
    CHECK(c40.shape < c20.shape);
  }
}

TEST_CASE("released from a shape bulging 20 m out of its plane, the line settles to the catenary") {
  const Comparison bent = compare(20, true, 400.0, 200.0, 20.0);
  const Comparison flat = compare(20, true, 400.0, 200.0, 0.0);
  CHECK(bent.fairlead == Approx(flat.fairlead).margin(1e-6));
  CHECK(bent.shape == Approx(flat.shape).margin(1e-6));
}

namespace {
// (line, r, v) => kinetic energy with the structural node masses, J
double kinetic(const LumpedLine& line, const Eigen::Matrix3Xd& v) {
  double e = 0.0;
  for (int i = 0; i < line.nodes(); ++i)
    e += 0.5 * line.properties().massPerLength * line.nodeLength(i) * v.col(i).squaredNorm();
  return e;
}
// (line, r, v, dt) => one RK4 step of the free nodes (ends held), structural masses only
void rk4(const LumpedLine& line, Eigen::Matrix3Xd& r, Eigen::Matrix3Xd& v, double dt) {
  const int n = line.nodes();
  Eigen::Matrix3Xd f(3, n);
  Eigen::VectorXd tension(n - 1);
  auto accel = [&](const Eigen::Matrix3Xd& rr, const Eigen::Matrix3Xd& vv) {
    line.nodeForces(rr, vv, 0.0, f, tension);
    Eigen::Matrix3Xd a = Eigen::Matrix3Xd::Zero(3, n);
    for (int i = 1; i + 1 < n; ++i)
      a.col(i) = f.col(i) / (line.properties().massPerLength * line.nodeLength(i));
    return a;
  };
  const Eigen::Matrix3Xd a1 = accel(r, v);
  const Eigen::Matrix3Xd r2 = r + 0.5 * dt * v, v2 = v + 0.5 * dt * a1;
  const Eigen::Matrix3Xd a2 = accel(r2, v2);
  const Eigen::Matrix3Xd r3 = r + 0.5 * dt * v2, v3 = v + 0.5 * dt * a2;
  const Eigen::Matrix3Xd a3 = accel(r3, v3);
  const Eigen::Matrix3Xd r4 = r + dt * v3, v4 = v + dt * a3;
  const Eigen::Matrix3Xd a4 = accel(r4, v4);
  r += dt / 6.0 * (v + 2.0 * v2 + 2.0 * v3 + v4);
  v += dt / 6.0 * (a1 + 2.0 * a2 + 2.0 * a3 + a4);
}
}  // namespace

TEST_CASE("energy: conserved without dissipation, only lost with damping and drag") {
  LumpedLineProperties p = chain(10, false);
  p.damping = 0.0;
  p.ea = 7.5e7;  // softer, for a step of 2 ms
  const LumpedLine line(p, "chain");
  const CatenaryParameters cp{500.0, p.ea, line.weightPerLength(), false, 0.0};
  const CatenarySolution s = solveCatenary(cp, 400.0, 200.0);
  Eigen::Matrix3Xd r = startShape(line, cp, s, 400.0, 5.0);  // swings back through its plane
  Eigen::Matrix3Xd v = Eigen::Matrix3Xd::Zero(3, line.nodes());
  const double e0 = line.potentialEnergy(r, 0.0);
  double maxKinetic = 0.0, maxDrift = 0.0;
  for (int k = 0; k < 5000; ++k) {  // 10 s
    rk4(line, r, v, 2e-3);
    maxKinetic = std::max(maxKinetic, kinetic(line, v));
    maxDrift = std::max(maxDrift, std::abs(kinetic(line, v) + line.potentialEnergy(r, 0.0) - e0));
  }
  CHECK(maxKinetic > 1e4);
  CHECK(maxDrift < 1e-6 * maxKinetic);
  // (internal damping and drag) => the energy never grows
  p.damping = -0.2;
  p.cdn = 1.2;
  p.cdt = 0.4;
  const LumpedLine lossy(p, "chain");
  r = startShape(lossy, cp, s, 400.0, 5.0);
  v.setZero();
  const double start = lossy.potentialEnergy(r, 0.0);
  double previous = start, lost = 0.0;
  bool grew = false;
  for (int k = 0; k < 5000; ++k) {
    rk4(lossy, r, v, 2e-3);
    const double e = kinetic(lossy, v) + lossy.potentialEnergy(r, 0.0);
    grew = grew || e > previous + 1e-9 * std::abs(e0);
    lost = start - e;
    previous = e;
  }
  CHECK_FALSE(grew);
  CHECK(lost > 0.5 * maxKinetic);
}

TEST_CASE("a segment: tension only, EA e + c de/dt with c a fraction of l sqrt(EA mu)") {
  LumpedLineProperties p = chain(1, false);
  p.length = 10.0;
  p.damping = -0.3;
  const LumpedLine line(p, "one");
  const double c = 0.3 * 10.0 * std::sqrt(7.5e8 * 120.0);
  CHECK(line.dampingCoefficient() == Approx(c));
  Eigen::Matrix3Xd r(3, 2), v = Eigen::Matrix3Xd::Zero(3, 2), f(3, 2);
  Eigen::VectorXd t(1);
  r.col(0) = Vector3::Zero();
  r.col(1) = Vector3(10.01, 0, 0);  // strain 1e-3
  v.col(1) = Vector3(0.2, 0.1, 0);  // strain rate 0.02 /s
  line.nodeForces(r, v, 0.0, f, t);
  const double T = 7.5e8 * 1e-3 + c * 0.02;
  CHECK(t[0] == Approx(T));
  const double w = line.weightPerLength();
  CHECK((f.col(0) - Vector3(T, 0, -0.5 * w * 10.0)).norm() < 1e-9 * T);
  CHECK((f.col(1) - Vector3(-T, 0, -0.5 * w * 10.0)).norm() < 1e-9 * T);
  // compressed, or stretched but closing fast: no push
  r.col(1) = Vector3(9.0, 0, 0);
  line.nodeForces(r, v, 0.0, f, t);
  CHECK(t[0] == 0.0);
  r.col(1) = Vector3(10.0 + 1e-7, 0, 0);
  v.col(1) = Vector3(-1.0, 0, 0);
  line.nodeForces(r, v, 0.0, f, t);
  CHECK(t[0] == 0.0);
}

TEST_CASE("Morison drag in a current, fluid inertia in waves, added mass, the sea bed") {
  LumpedLineProperties p = chain(1, false);
  p.length = 10.0;
  p.cdn = 1.2;
  p.cdt = 0.5;
  p.can = 1.0;
  p.cat = 0.2;
  const double rho = 1025.0, d = 0.12, V = 0.25 * std::numbers::pi * d * d * 5.0;  // end node
  Eigen::Matrix3Xd r(3, 2), v = Eigen::Matrix3Xd::Zero(3, 2), f(3, 2);
  Eigen::VectorXd t(1);
  r.col(0) = Vector3(0, 0, -50);
  r.col(1) = Vector3(9.0, 0, -50);  // slack: no tension, only the node loads
  SECTION("drag on the flow relative to the node, normal and tangential") {
    CurrentProperties cprops;
    cprops.speed = 1.0;
    cprops.direction = std::numbers::pi / 2;  // toward +y
    const CurrentField current(cprops);
    const LumpedLine line(p, "one", nullptr, &current);
    v.col(1) = Vector3(0.3, 0.4, 0.0);
    line.nodeForces(r, v, 0.0, f, t);
    const Vector3 vt(-0.3, 0, 0), vn(0, 0.6, 0);  // relative flow along and across the line
    const double ls = 4.5;                        // half the stretched segment
    const Vector3 drag =
        0.5 * rho * d * ls * (1.2 * vn.norm() * vn + 0.5 * std::numbers::pi * vt.norm() * vt);
    const Vector3 weight(0, 0, -line.weightPerLength() * 5.0);
    CHECK((f.col(1) - drag - weight).norm() < 1e-10 * drag.norm());
  }
  SECTION("fluid inertia rho V [(1 + Can) a_n + (1 + Cat) a_t] of the waves, added mass") {
    WaterProperties water;
    water.depth = 200.0;
    const AiryWaves waves(water, {{3.0, 9.0, 0.3, 0.0}});
    p.cdn = p.cdt = 0.0;
    const LumpedLine line(p, "one", &waves);
    const double time = 2.0;
    line.nodeForces(r, v, time, f, t);
    const Vector3 a = waves.acceleration(r.col(1), time);
    const Vector3 at(a.x(), 0, 0), an = a - at;
    const Vector3 expected =
        rho * V * (2.0 * an + 1.2 * at) + Vector3(0, 0, -line.weightPerLength() * 5.0);
    CHECK(a.norm() > 0.01);
    CHECK((f.col(1) - expected).norm() < 1e-10 * expected.norm());
    std::vector<Matrix3> m(2);
    line.nodeMass(r, 0.0, m);
    Matrix3 qq = Matrix3::Zero();
    qq(0, 0) = 1.0;
    const Matrix3 expectedMass =
        120.0 * 5.0 * Matrix3::Identity() + rho * V * (1.0 * (Matrix3::Identity() - qq) + 0.2 * qq);
    CHECK((m[1] - expectedMass).norm() < 1e-12 * expectedMass.norm());
  }
  SECTION("the bed: kb d l_n times the depth below it, friction mu N against the sliding") {
    p.cdn = p.cdt = p.can = p.cat = 0.0;
    p.seabed = true;
    p.seabedZ = -49.99;  // node 1 is 1 cm below it
    p.bedStiffness = 1e6;
    p.bedDamping = 0.0;
    p.bedFriction = 0.6;
    const LumpedLine line(p, "one");
    v.col(1) = Vector3(0.3, -0.4, 0.0);  // sliding at 0.5 m/s
    line.nodeForces(r, v, 0.0, f, t);
    const double normal = 0.01 * 1e6 * d * 5.0;
    const Vector3 expected = Vector3(0, 0, normal - line.weightPerLength() * 5.0) -
                             0.6 * normal * Vector3(0.3, -0.4, 0.0) / 0.5;
    CHECK((f.col(1) - expected).norm() < 1e-9 * normal);
    CHECK(line.potentialEnergy(r, 0.0) ==
          Approx(2 * 0.5 * 1e6 * d * 5.0 * 1e-4 + line.weightPerLength() * 5.0 * (-50.0 - 50.0)));
  }
  LumpedLineProperties bad = p;
  bad.segments = 0;
  CHECK_THROWS_AS(LumpedLine(bad, "bad"), std::invalid_argument);
  bad = p;
  bad.cdn = -1.0;
  CHECK_THROWS_AS(LumpedLine(bad, "bad"), std::invalid_argument);
}

namespace {

// (line, r, v, which: 0 positions, 1 velocities) => d f / d x by central differences, 3 nodes x
// 3 nodes, with a step of 1e-6 m or m/s
Eigen::MatrixXd centralJacobian(const LumpedLine& line, const Eigen::Matrix3Xd& r,
                                const Eigen::Matrix3Xd& v, int which) {
  const int n = line.nodes();
  Eigen::MatrixXd J(3 * n, 3 * n);
  Eigen::Matrix3Xd fp(3, n), fm(3, n);
  Eigen::VectorXd tension(n - 1);
  const double h = 1e-6;
  for (int j = 0; j < 3 * n; ++j) {
    Eigen::Matrix3Xd rp = r, vp = v, rm = r, vm = v;
    (which == 0 ? rp : vp)(j % 3, j / 3) += h;
    (which == 0 ? rm : vm)(j % 3, j / 3) -= h;
    line.nodeForces(rp, vp, 0.0, fp, tension);
    line.nodeForces(rm, vm, 0.0, fm, tension);
    J.col(j) = Eigen::Map<const Eigen::VectorXd>(fp.data(), 3 * n) / (2 * h) -
               Eigen::Map<const Eigen::VectorXd>(fm.data(), 3 * n) / (2 * h);
  }
  return J;
}

// (blocks per node, slot 3 i + j - i + 1) => the dense 3 nodes x 3 nodes matrix
Eigen::MatrixXd denseBlocks(const std::vector<Matrix3>& b, int nodes) {
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(3 * nodes, 3 * nodes);
  for (int i = 0; i < nodes; ++i)
    for (int j = std::max(0, i - 1); j <= std::min(nodes - 1, i + 1); ++j)
      J.block<3, 3>(3 * i, 3 * j) = b[static_cast<std::size_t>(3 * i + j - i + 1)];
  return J;
}

}  // namespace

TEST_CASE("the line's force Jacobian equals central differences: taut and slack, bed, friction") {
  // (6 segments of 10 m: taut ones stretched 0.5 %, slack ones 5 % short; nodes 1 and 2 pressed
  // 5 mm into the bed with friction, node 1 sliding at 0.1 m/s, node 2 below the regularising
  // speed; every node moving) => df/dr without drag (the drag's position terms are left out by
  // design) and df/dv with drag, block by block, against central differences
  LumpedLineProperties p = chain(6, true);
  p.length = 60.0;
  p.bedFriction = 0.5;
  p.seabedZ = -0.005;  // nodes 1 and 2 5 mm into it, the anchor above it
  p.cdn = 0.0;
  p.cdt = 0.0;
  const std::vector<double> lengths{10.05, 9.5, 10.05, 10.05, 9.5, 10.05};
  Eigen::Matrix3Xd r(3, 7), v(3, 7);
  r.col(0) = Vector3(0.0, 0.0, 0.0);
  const std::vector<Vector3> dirs{{1, 0, -0.001}, {1, 0, 0},     {1, -0.1, 0.3},
                                  {1, 0.3, 0.5},  {0.8, 0.1, 1}, {1, -0.2, 0.7}};
  for (int i = 0; i < 6; ++i)
    r.col(i + 1) = r.col(i) + lengths[static_cast<std::size_t>(i)] *
                                  dirs[static_cast<std::size_t>(i)].normalized();
  for (int i = 0; i < 7; ++i) v.col(i) = Vector3(0.03 * i, -0.02 * i, 0.01 * (i % 3));
  v.col(1) = Vector3(0.1, 0.02, 0.05);
  v.col(2) = Vector3(2e-4, -1e-4, 0.01);
  std::vector<Matrix3> dfdr(21), dfdv(21);
  const auto check = [&](const LumpedLine& line, int which) {
    line.forceJacobian(r, v, 0.0, dfdr, dfdv);
    const Eigen::MatrixXd A = denseBlocks(which == 0 ? dfdr : dfdv, 7);
    const Eigen::MatrixXd N = centralJacobian(line, r, v, which);
    for (int i = 0; i < 7; ++i)
      for (int j = 0; j < 7; ++j) {
        const Eigen::Matrix3d a = A.block<3, 3>(3 * i, 3 * j), c = N.block<3, 3>(3 * i, 3 * j);
        INFO((which == 0 ? "df/dr" : "df/dv") << " block " << i << ", " << j << "\nclosed form\n"
                                              << a << "\ncentral\n"
                                              << c);
        CHECK((a - c).norm() <= 1e-6 * c.norm() + 1e-2);
        if (std::abs(i - j) > 1) CHECK(c.norm() == 0.0);
      }
    CHECK(A.norm() > 1e7);  // EA/l = 7.5e7 N/m or c/l = 1.6e5 N s/m: something is compared
  };
  check(LumpedLine(p, "still"), 0);
  check(LumpedLine(p, "still"), 1);
  p.cdn = 1.2;
  p.cdt = 0.4;
  check(LumpedLine(p, "drag"), 1);
  // (the switches) => the signature changes when a segment goes slack or a node leaves the bed
  const LumpedLine line(p, "drag");
  const std::uint64_t s0 = line.forceJacobian(r, v, 0.0, dfdr, dfdv);
  CHECK(line.forceJacobian(r, v, 0.0, dfdr, dfdv) == s0);
  Eigen::Matrix3Xd moved = r;
  moved.col(6) -= 0.2 * (r.col(6) - r.col(5));  // the last segment 20 % shorter: slack
  CHECK(line.forceJacobian(moved, v, 0.0, dfdr, dfdv) != s0);
  moved = r;
  moved(2, 2) = 0.0;  // node 2 above the bed
  CHECK(line.forceJacobian(moved, v, 0.0, dfdr, dfdv) != s0);
}
