// A lumped line's bending stiffness (forces/lines/lumped_line_bending.hpp): its node forces are
// the exact negative gradient of its energy and its Jacobian blocks (a 5-node stencil) equal
// central differences; a taut line pinned at both ends rings at the tensioned beam's first
// frequency f1 = (1 / 2L) sqrt(T / m') sqrt(1 + pi^2 EI / (T L^2)) within 1 % at 20 segments,
// converging at second order; a line spanned between pinned ends sags under its own weight as the
// beam's 5 w L^4 / (384 EI); a stiff chain lying on the sea bed starts at its own rest, a minimum
// of its energy; RK4 conserves its energy with a drift falling at fourth order; a line without
// bending (EI = 0) keeps the 3-block Jacobian layout.
#include "forces/lines/lumped_line_bending.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <Eigen/Eigenvalues>

#include "forces/lines/lumped_line.hpp"
#include "forces/lines/lumped_line_provider.hpp"
#include "forces/lines/lumped_line_statics.hpp"

using namespace yardsim;
using namespace yardsim::forces;
using dynamics::Matrix3;
using dynamics::Vector3;

namespace {

// (segments, EI) => a 10 m steel-pipe-like line in air: 50 kg/m, d 0.1 m, EA 1e8 N, no drag
LumpedLineProperties pipe(int segments, double ei) {
  LumpedLineProperties p;
  p.length = 10.0;
  p.segments = segments;
  p.diameter = 0.1;
  p.massPerLength = 50.0;
  p.ea = 1e8;
  p.ei = ei;
  p.damping = 0.0;
  p.waterDensity = 1.225;
  return p;
}

// (n nodes) => a bent, stretched 3D shape: every segment about 1.5 m, turning by up to 0.6 rad
Eigen::Matrix3Xd bent(int nodes) {
  Eigen::Matrix3Xd r(3, nodes);
  r.col(0) = Vector3(0.3, -0.2, 1.0);
  for (int i = 1; i < nodes; ++i) {
    const Vector3 dir(1.0, 0.4 * std::sin(1.3 * i), 0.5 * std::cos(0.7 * i));
    r.col(i) = r.col(i - 1) + (1.5 + 0.01 * i) * dir.normalized();
  }
  return r;
}

// (line, r, v, which: 0 positions, 1 velocities) => d f / d x by central differences (dense)
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
    J.col(j) = (Eigen::Map<const Eigen::VectorXd>(fp.data(), 3 * n) -
                Eigen::Map<const Eigen::VectorXd>(fm.data(), 3 * n)) /
               (2 * h);
  }
  return J;
}

// (line, r) => the transverse (y) frequencies of the line straight along x, both ends held:
// the y-y block of the stiffness by central differences of the node forces, over the node masses
Eigen::VectorXd transverseFrequencies(const LumpedLine& line, const Eigen::Matrix3Xd& r) {
  const int inner = line.nodes() - 2;
  const Eigen::Matrix3Xd v = Eigen::Matrix3Xd::Zero(3, line.nodes());
  const Eigen::MatrixXd J = centralJacobian(line, r, v, 0);
  Eigen::MatrixXd K(inner, inner);
  for (int i = 0; i < inner; ++i)
    for (int j = 0; j < inner; ++j) K(i, j) = -J(3 * (i + 1) + 1, 3 * (j + 1) + 1);
  const double m = line.properties().massPerLength * line.segmentLength();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(0.5 * (K + K.transpose()) / m);
  return eig.eigenvalues().cwiseMax(0.0).cwiseSqrt() / (2.0 * std::numbers::pi);
}

}  // namespace

TEST_CASE("bending: the node forces are minus the gradient of the energy, for any shape") {
  // (a bent, stretched line, EI 2e5 N m^2) => conservativeForces = -dV/dr by central differences
  // of potentialEnergy (which holds the bending energy), and nodeForces = conservativeForces
  // without damping, drag or bed
  LumpedLineProperties p = pipe(7, 2e5);
  p.length = 7 * 1.5;
  const LumpedLine line(p, "pipe");
  const Eigen::Matrix3Xd r = bent(8);
  Eigen::Matrix3Xd f(3, 8), g(3, 8);
  Eigen::VectorXd tension(7);
  line.conservativeForces(r, 0.0, f);
  line.nodeForces(r, Eigen::Matrix3Xd::Zero(3, 8), 0.0, g, tension);
  CHECK((f - g).norm() <= 1e-12 * f.norm());
  const double h = 1e-6;
  double worst = 0.0, bendingScale = 0.0;
  for (int i = 0; i < 8; ++i)
    for (int k = 0; k < 3; ++k) {
      Eigen::Matrix3Xd rp = r, rm = r;
      rp(k, i) += h;
      rm(k, i) -= h;
      const double dv = (line.potentialEnergy(rp, 0.0) - line.potentialEnergy(rm, 0.0)) / (2 * h);
      worst = std::max(worst, std::abs(f(k, i) + dv));
      // (the bending alone) => its own gradient
      const double db = (bendingEnergy(rp, p.ei / line.segmentLength()) -
                         bendingEnergy(rm, p.ei / line.segmentLength())) /
                        (2 * h);
      Eigen::Matrix3Xd fb = Eigen::Matrix3Xd::Zero(3, 8);
      addBendingForces(r, p.ei / line.segmentLength(), fb);
      CHECK(fb(k, i) == Approx(-db).margin(1e-6 * p.ei));
      bendingScale = std::max(bendingScale, std::abs(fb(k, i)));
    }
  INFO("largest |f + dV/dr| " << worst << " N, largest bending force " << bendingScale << " N");
  CHECK(bendingScale > 1e4);  // (the bending is there: EI / l^2 ~ 9e4 N)
  CHECK(worst <= 1e-7 * f.cwiseAbs().maxCoeff());
  // (small angles) => E = EI theta^2 / (2 l) at a node turned by theta
  const double theta = 1e-3, l = line.segmentLength();
  Eigen::Matrix3Xd kink(3, 3);
  kink << 0.0, l, l + l * std::cos(theta), 0.0, 0.0, l * std::sin(theta), 0.0, 0.0, 0.0;
  CHECK(bendingEnergy(kink, p.ei / l) == Approx(p.ei * theta * theta / (2 * l)).epsilon(1e-6));
  // (EI < 0 or not finite) => refused
  p.ei = -1.0;
  CHECK_THROWS_AS(LumpedLine(p, "bad"), std::invalid_argument);
  p.ei = std::nan("");
  CHECK_THROWS_AS(LumpedLine(p, "bad"), std::invalid_argument);
}

TEST_CASE("bending: the Jacobian's 5-node blocks equal central differences") {
  // (a bent line, taut and slack segments, internal damping, every node moving) => df/dr and
  // df/dv block by block, nodes i - 2 .. i + 2, zero beyond
  LumpedLineProperties p = pipe(7, 3e5);
  p.length = 7 * 1.5;
  p.damping = -0.5;
  const Eigen::Matrix3Xd r = bent(8);
  Eigen::Matrix3Xd v(3, 8);
  for (int i = 0; i < 8; ++i) v.col(i) = Vector3(0.03 * i, -0.02 * i, 0.01 * (i % 3));
  for (double length : {7 * 1.5, 7 * 1.545}) {  // (all taut; then some slack)
    p.length = length;
    const LumpedLine line(p, "pipe");
    REQUIRE(line.jacobianBandwidth() == 2);
    std::vector<Matrix3> dfdr(5 * 8), dfdv(5 * 8);
    line.forceJacobian(r, v, 0.0, dfdr, dfdv);
    for (int which = 0; which < 2; ++which) {
      const Eigen::MatrixXd N = centralJacobian(line, r, v, which);
      double farthest = 0.0;  // (the largest |i - j| = 2 block: the bending's reach)
      for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j) {
          const Eigen::Matrix3d c = N.block<3, 3>(3 * i, 3 * j);
          if (std::abs(i - j) > 2) {
            CHECK(c.norm() == 0.0);
            continue;
          }
          const Matrix3& a =
              (which == 0 ? dfdr : dfdv)[static_cast<std::size_t>(5 * i + j - i + 2)];
          INFO((which == 0 ? "df/dr" : "df/dv")
               << " block " << i << ", " << j << " length " << length << "\nclosed form\n"
               << a << "\ncentral\n"
               << c);
          CHECK((a - c).norm() <= 1e-6 * c.norm() + 1e-2);
          if (std::abs(i - j) == 2) farthest = std::max(farthest, c.norm());
        }
      if (which == 0) CHECK(farthest > 1e4);  // (EI / l^3 = 9e4 N/m)
    }
  }
  // (EI = 0) => the 3-block layout of the line without bending
  CHECK(LumpedLine(pipe(7, 0.0), "plain").jacobianBandwidth() == 1);
}

TEST_CASE("bending: a taut pinned-pinned line rings at the tensioned beam's first frequency") {
  // (10 m, 50 kg/m, stretched to T = 1e4 N along x, EI = 2e4 N m^2: pi^2 EI / (T L^2) = 0.2) =>
  // f1 = (1 / 2L) sqrt(T / m') sqrt(1 + pi^2 EI / (T L^2)) with L and m' per stretched metre
  const double T = 1e4, ei = 2e4;
  double previous = 1.0;
  for (int n : {10, 20, 40}) {
    const LumpedLine line(pipe(n, ei), "pipe");
    const double strain = T / 1e8, L = 10.0 * (1.0 + strain), m = 50.0 / (1.0 + strain);
    Eigen::Matrix3Xd r(3, n + 1);
    for (int i = 0; i <= n; ++i) r.col(i) = Vector3(L * i / n, 0.0, 0.0);
    const Eigen::VectorXd f = transverseFrequencies(line, r);
    const double pi2 = std::numbers::pi * std::numbers::pi;
    const double exact = std::sqrt(T / m) / (2.0 * L) * std::sqrt(1.0 + pi2 * ei / (T * L * L));
    const double string = std::sqrt(T / m) / (2.0 * L);
    const double err = std::abs(f[0] / exact - 1.0);
    INFO(n << " segments: f1 " << f[0] << " Hz against " << exact << " Hz (the string alone "
           << string << " Hz), error " << err);
    CHECK(f[0] > 1.05 * string);  // (the bending raises it by 9.5 %)
    if (n == 20) CHECK(err < 0.01);
    CHECK(err < previous / 3.0);  // (second order: a quarter per halving)
    previous = err;
  }
}

TEST_CASE("bending: a line spanned between pinned ends sags as a beam under its own weight") {
  // (10 m spanned exactly between two ends 10 m apart, 50 kg/m in air, EI 1e7 N m^2, EA 1e7 N:
  // sag 6.4 mm, the stretch's tension T ~ EA (8/3) (sag / L)^2 ~ 11 N, T L^2 / (pi^2 EI) ~ 1e-5)
  // => mid-span deflection 5 w L^4 / (384 EI)
  // (Euler-Bernoulli, simply supported, uniform load) from the chain's static equilibrium
  const double ei = 1e7;
  double previous = 1.0;
  for (int n : {10, 20, 40}) {
    LumpedLineProperties p = pipe(n, ei);
    p.ea = 1e7;
    const LumpedLine line(p, "pipe");
    Eigen::Matrix3Xd r(3, n + 1);
    for (int i = 0; i <= n; ++i) r.col(i) = Vector3(10.0 * i / n, 0.0, 0.0);
    REQUIRE(lumpedLineStatics(line, r));
    const double w = line.weightPerLength();
    const double exact = 5.0 * w * std::pow(10.0, 4) / (384.0 * ei);
    const double sag = -r(2, n / 2);
    const double err = std::abs(sag / exact - 1.0);
    INFO(n << " segments: sag " << sag << " m against " << exact << " m, error " << err);
    CHECK(std::abs(r(1, n / 2)) < 1e-12);
    if (n == 20) CHECK(err < 0.01);
    CHECK(err < previous / 3.0);
    previous = err;
  }
}

TEST_CASE("bending: a stiff chain lying on the sea bed starts at its own rest") {
  // (the moored buoy's chain, tests/mechanics/mechanics_fixture.hpp: 314 m of 8 segments from an
  // anchor on the bed to a fairlead 290 m away and 39 m up, about a third laid, EI from a wire's to
  // a steel pipe's) => lumpedLineNodes finds the chain's own equilibrium from the catenary's points
  // (until 2026-11-29 its Newton stalled on the bed's kink from EI ~ 1e8 N m^2 and the line
  // started from the catenary's points, falling: HHT then failed dozens of Newton solves)
  for (const double ei : {1e8, 1e10}) {
    INFO("EI " << ei);
    LumpedLineProperties p;
    p.length = 314.0;
    p.segments = 8;
    p.diameter = 0.216;
    p.massPerLength = 282.21;
    p.ea = 1.2e9;
    p.ei = ei;
    p.seabed = true;
    p.bedStiffness = 3e6;
    p.bedDamping = 3e5;
    const LumpedLine line(p, "chain");
    const Vector3 pA(0.0, 0.0, 0.0), pB(290.0, 0.0, 39.0);
    const std::vector<LumpedNodeBody> nodes = lumpedLineNodes(line, "chain", pA, pB);
    Eigen::Matrix3Xd r(3, p.segments + 1), f(3, p.segments + 1);
    r.col(0) = pA;
    r.col(p.segments) = pB;
    for (int i = 1; i < p.segments; ++i) r.col(i) = nodes[static_cast<std::size_t>(i - 1)].p_W;
    // (at rest) => no node force beyond the statics' tolerance, 1e-9 of the line's weight
    const double weight = line.weightPerLength() * p.length;
    line.conservativeForces(r, 0.0, f);
    CHECK(f.middleCols(1, p.segments - 1).cwiseAbs().maxCoeff() < 1e-9 * weight);
    // (a rest a line can keep) => a minimum: moving any inner node 1 cm any way does not lower
    // the energy (beyond its rounding)
    const double v0 = line.potentialEnergy(r, 0.0);
    for (int i = 1; i < p.segments; ++i)
      for (int k = 0; k < 3; ++k)
        for (const double d : {-0.01, 0.01}) {
          Eigen::Matrix3Xd moved = r;
          moved(k, i) += d;
          CHECK(line.potentialEnergy(moved, 0.0) > v0 - 1e-9 * std::abs(v0));
        }
    // (some of it lies on the bed, within a diameter of it) => the laid part is there
    CHECK(r(2, 1) < p.diameter);
  }
}

TEST_CASE("bending: RK4 conserves the energy of a swinging stiff line, drift at fourth order") {
  // (a 10 m line of 10 segments pinned at both ends, EI 2e3 N m^2, EA 1e6 N, spanned 0.2 %
  // longer than its length (taut) and released from a transverse bow) => kinetic + potential
  // (strain, bending, weight) drifts by RK4's error only, about 16 times less at half the step
  LumpedLineProperties p = pipe(10, 2e3);
  p.ea = 1e6;
  const LumpedLine line(p, "pipe");
  const int n = 11;
  auto run = [&](double dt) {
    Eigen::Matrix3Xd r(3, n), v = Eigen::Matrix3Xd::Zero(3, n), f(3, n);
    for (int i = 0; i < n; ++i)
      r.col(i) = Vector3(10.02 * i / 10.0, 0.3 * std::sin(std::numbers::pi * i / 10.0), 0.0);
    Eigen::VectorXd tension(n - 1);
    const double m = p.massPerLength * line.segmentLength();
    auto accel = [&](const Eigen::Matrix3Xd& x, const Eigen::Matrix3Xd& u) {
      line.nodeForces(x, u, 0.0, f, tension);
      Eigen::Matrix3Xd a = f / m;
      a.col(0).setZero();
      a.col(n - 1).setZero();
      return a;
    };
    auto energy = [&](const Eigen::Matrix3Xd& x, const Eigen::Matrix3Xd& u) {
      return line.potentialEnergy(x, 0.0) + 0.5 * m * u.squaredNorm();
    };
    const double e0 = energy(r, v);
    double drift = 0.0, bendingSwing = 0.0;
    const double b0 = bendingEnergy(r, p.ei / line.segmentLength());
    for (double t = 0.0; t < 1.0 - 1e-12; t += dt) {
      const Eigen::Matrix3Xd k1v = accel(r, v), k1r = v;
      const Eigen::Matrix3Xd k2v = accel(r + 0.5 * dt * k1r, v + 0.5 * dt * k1v),
                             k2r = v + 0.5 * dt * k1v;
      const Eigen::Matrix3Xd k3v = accel(r + 0.5 * dt * k2r, v + 0.5 * dt * k2v),
                             k3r = v + 0.5 * dt * k2v;
      const Eigen::Matrix3Xd k4v = accel(r + dt * k3r, v + dt * k3v), k4r = v + dt * k3v;
      r += dt / 6.0 * (k1r + 2.0 * k2r + 2.0 * k3r + k4r);
      v += dt / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
      drift = std::max(drift, std::abs(energy(r, v) - e0));
      bendingSwing =
          std::max(bendingSwing, std::abs(bendingEnergy(r, p.ei / line.segmentLength()) - b0));
    }
    return std::array<double, 2>{drift, bendingSwing};
  };
  const auto coarse = run(2e-3), fine = run(1e-3);
  INFO("drift " << coarse[0] << " J at 2 ms, " << fine[0] << " J at 1 ms; bending energy swing "
                << fine[1] << " J");
  CHECK(fine[1] > 10.0);  // (the bending takes part: 39 J measured)
  CHECK(fine[0] < 1e-5 * fine[1]);
  CHECK(coarse[0] > 10.0 * fine[0]);
}
