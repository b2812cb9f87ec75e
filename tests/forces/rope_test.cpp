// The wire rope against closed forms: static stretch of a hanging block, the bounce frequency
// sqrt(n EA/L0 / m), a slack rope that exerts nothing (free fall until taut, then the peak
// stretch from energy), damping only while taut, multi-part reeving, a rope over a sheave, a
// winch paying out and hauling in with the energy balance, the breaking load, refused input.
#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

#include "force_rig.hpp"
#include "forces/gravity.hpp"
#include "forces/rope.hpp"

using namespace yardsim;
using namespace yardsim::forces;
using namespace yardsim::forces::testing;
using Catch::Matchers::Contains;

namespace {

const Vector3 kG(0.0, 0.0, -9.81);
constexpr double kMass = 200e3;     // a 200 t block, kg
constexpr double kEA = 1e9;         // N
constexpr double kL0 = 30.0;        // m
constexpr double kTop = 40.0;       // height of the crane's point, m
const Vector3 kLug(0.0, 0.0, 0.5);  // the block's lug in the block frame

RopeProperties rope(double dampingRatio, int parts = 1) {
  RopeProperties p;
  p.ea = kEA;
  p.l0 = kL0;
  // (zeta, stiffness of the n parts together) => c of one part, N s/m
  p.damping = dampingRatio * 2.0 * std::sqrt(parts * kEA / kL0 * kMass) / parts;
  return p;
}

// A block on a vertical slide hanging from the world point (0, 0, kTop) by a rope of n parts.
struct HangingBlock {
  explicit HangingBlock(const RopeProperties& p, int parts = 1)
      : model(verticalBlock(kMass)),
        gravity("gravity", kG),
        wire("hoist", model, {{0, Vector3(0.0, 0.0, kTop)}, {1, kLug}}, p, parts),
        rig(model, {&gravity, &wire}) {}
  // (rope length L) => the block's height q
  static double heightFor(double length) { return kTop - kLug.z() - length; }
  double ropeLength() const { return kTop - kLug.z() - rig.q[0]; }

  dynamics::Model model;
  Gravity gravity;
  Rope wire;
  Rig rig;
};

// (rope, stage) => the force on the block (body 1) and the generalized force
struct Evaluated {
  dynamics::Force F_W;
  Eigen::VectorXd tau;
};
Evaluated evaluate(ForceProvider& p, const Stage& s) {
  dynamics::ExternalForces f(s.model);
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(s.model.nv);
  p.evaluate(s, f, tau);
  return {f.worldFrame(1), tau};
}

}  // namespace

TEST_CASE("a block settles on a damped rope at T = m g with stretch m g L0 / EA") {
  HangingBlock hb(rope(0.2));
  hb.rig.q[0] = HangingBlock::heightFor(kL0);  // released with the rope just straight
  for (int k = 0; k < 8000; ++k) hb.rig.step(1e-3);
  const Stage s = hb.rig.stage();
  CHECK(std::abs(hb.rig.v[0]) < 1e-8);
  CHECK(hb.wire.tension(s) == Approx(kMass * 9.81).epsilon(1e-8));
  CHECK(hb.wire.length(s) - kL0 == Approx(kMass * 9.81 * kL0 / kEA).epsilon(1e-7));
  CHECK(hb.wire.length(s) == Approx(hb.ropeLength()).epsilon(1e-14));
  CHECK(hb.wire.isTaut(s));
  CHECK(evaluate(hb.wire, s).F_W[5] == Approx(kMass * 9.81).epsilon(1e-6));
  // (at rest) => the potential energy is the strain energy k e^2 / 2, no power
  const double e = hb.wire.length(s) - kL0;
  CHECK(hb.wire.potentialEnergy(s) == Approx(0.5 * kEA / kL0 * e * e).epsilon(1e-12));
  CHECK(std::abs(hb.wire.power(s)) < 1e-6 * kMass * 9.81);
}

TEST_CASE("an undamped block bounces at sqrt(k / m) with k = n EA / L0") {
  for (int parts : {1, 4}) {
    HangingBlock hb(rope(0.0, parts), parts);
    const double k = parts * kEA / kL0, omega = std::sqrt(k / kMass),
                 zEq = HangingBlock::heightFor(kL0 + kMass * 9.81 / k);
    const double delta = 0.2 * kMass * 9.81 / k;  // stays taut
    hb.rig.q[0] = zEq + delta;
    double worst = 0.0;
    for (int i = 0; i < 2000; ++i) {
      hb.rig.step(1e-3);
      worst = std::max(worst, std::abs(hb.rig.q[0] - (zEq + delta * std::cos(omega * hb.rig.t))));
    }
    INFO("parts = " << parts);
    CHECK(worst < 1e-6 * delta);
  }
}

TEST_CASE("a slack rope exerts nothing: free fall until taut and then the stretch energy says") {
  HangingBlock hb(rope(0.0));
  const double drop = 0.5, z0 = HangingBlock::heightFor(kL0 - drop), g = 9.81;
  hb.rig.q[0] = z0;
  const double tTaut = std::sqrt(2.0 * drop / g);
  // (slack) => no force at all, even moving
  hb.rig.v[0] = -1.0;
  const Evaluated slack = evaluate(hb.wire, hb.rig.stage());
  CHECK(slack.F_W.isZero(0.0));
  CHECK(hb.wire.tension(hb.rig.stage()) == 0.0);
  CHECK_FALSE(hb.wire.isTaut(hb.rig.stage()));
  hb.rig.v[0] = 0.0;
  // (until taut) => z0 - g t^2 / 2 (RK4 is exact on a parabola)
  const double h = 1e-3;
  while (hb.rig.t + h < tTaut) {
    hb.rig.step(h);
    CHECK(std::abs(hb.rig.q[0] - (z0 - 0.5 * g * hb.rig.t * hb.rig.t)) < 1e-10);
    CHECK(hb.wire.tension(hb.rig.stage()) == 0.0);
  }
  // (energy, no damping) => lowest point where m g (drop + x) = k x^2 / 2
  const double k = kEA / kL0, w = kMass * g;
  const double xMax = (w + std::sqrt(w * w + 2.0 * k * w * drop)) / k;
  double lowest = hb.rig.q[0];
  while (hb.rig.t < tTaut + 0.5) {
    hb.rig.step(h);
    lowest = std::min(lowest, hb.rig.q[0]);
  }
  CHECK(HangingBlock::heightFor(kL0) - lowest == Approx(xMax).epsilon(1e-4));
}

TEST_CASE("damping acts only while taut and never makes the rope push") {
  HangingBlock hb(rope(0.5));
  const double c = hb.wire.properties().damping, k = kEA / kL0;
  // (taut, stretching) => k e + c e'
  const double e = 0.01;
  hb.rig.q[0] = HangingBlock::heightFor(kL0 + e);
  hb.rig.v[0] = -0.2;  // the block moves down: the rope lengthens at 0.2 m/s
  CHECK(hb.wire.tension(hb.rig.stage()) == Approx(k * e + c * 0.2).epsilon(1e-12));
  CHECK(evaluate(hb.wire, hb.rig.stage()).F_W[5] == Approx(k * e + c * 0.2).epsilon(1e-12));
  // (taut, shortening fast) => k e - c |e'| < 0 is clamped to 0: no force
  hb.rig.v[0] = 2.0 * k * e / c;
  CHECK(hb.wire.isTaut(hb.rig.stage()));
  CHECK(hb.wire.tension(hb.rig.stage()) == 0.0);
  CHECK(evaluate(hb.wire, hb.rig.stage()).F_W.isZero(0.0));
  // (slack, lengthening) => no damping force either
  hb.rig.q[0] = HangingBlock::heightFor(kL0 - 0.01);
  hb.rig.v[0] = -0.5;
  CHECK(evaluate(hb.wire, hb.rig.stage()).F_W.isZero(0.0));
}

TEST_CASE("n parts: n T on the block and per part tension m g / n and stretch m g L0 / (n EA)") {
  const int n = 4;
  HangingBlock hb(rope(0.3, n), n);
  hb.rig.q[0] = HangingBlock::heightFor(kL0);
  for (int k = 0; k < 6000; ++k) hb.rig.step(1e-3);
  const Stage s = hb.rig.stage();
  const double w = kMass * 9.81;
  CHECK(std::abs(hb.rig.v[0]) < 1e-8);
  CHECK(hb.wire.tension(s) == Approx(w / n).epsilon(1e-8));
  CHECK(hb.wire.length(s) - kL0 == Approx(w / (n * kEA / kL0)).epsilon(1e-7));
  // (at rest, evaluate) => the block feels n T upward at its lug
  const Evaluated ev = evaluate(hb.wire, s);
  CHECK(ev.F_W[5] == Approx(n * hb.wire.tension(s)).epsilon(1e-14));
  CHECK(ev.F_W[5] == Approx(w).epsilon(1e-8));
  // (strain energy of n parts) => n k e^2 / 2
  const double e = hb.wire.length(s) - kL0;
  CHECK(hb.wire.potentialEnergy(s) == Approx(n * 0.5 * kEA / kL0 * e * e).epsilon(1e-12));
}

TEST_CASE("over a sheave: the length sums the segments and the sheave body feels T (u1 + u2)") {
  // a trolley (body 1) sliding along x carries the sheave; the block (body 2) slides vertically
  dynamics::ModelBuilder b;
  b.setGravity(Vector3::Zero());
  b.addBody("trolley", "world", dynamics::Joint::prismatic(Vector3::UnitX()),
            dynamics::Transform::translation(Vector3(0.0, 0.0, kTop)),
            dynamics::boxInertia(5e3, Vector3(1, 1, 1)));
  b.addBody("block", "world", dynamics::Joint::prismatic(Vector3::UnitZ()),
            dynamics::Transform::translation(Vector3(3.0, 0.0, 0.0)),
            dynamics::boxInertia(kMass, Vector3(2, 2, 1)));
  const dynamics::Model m = b.build();
  const Vector3 drum(-20.0, 0.0, 30.0), sheave(0.0, 0.5, -0.5);
  RopeProperties p = rope(0.0);
  p.l0 = 50.0;
  Rope wire("hoist", m, {{0, drum}, {1, sheave}, {2, kLug}}, p);
  Rig r(m, {&wire});
  r.q << 1.5, 5.0;
  r.v << 0.3, -0.7;
  const Stage s = r.stage();
  const Vector3 pS(1.5, 0.5, kTop - 0.5), pB(3.0, 0.0, 5.5);
  const double l1 = (pS - drum).norm(), l2 = (pB - pS).norm();
  CHECK(wire.length(s) == Approx(l1 + l2).epsilon(1e-14));
  // (rate) => u1 . v_sheave + u2 . (v_block - v_sheave)
  const Vector3 u1 = (pS - drum) / l1, u2 = (pB - pS) / l2, vS(0.3, 0.0, 0.0), vB(0.0, 0.0, -0.7);
  CHECK(wire.lengthRate(s) == Approx(u1.dot(vS) + u2.dot(vB - vS)).epsilon(1e-14));
  const double T = kEA / p.l0 * (l1 + l2 - p.l0);
  REQUIRE(T > 0.0);
  dynamics::ExternalForces f(m);
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(m.nv);
  wire.evaluate(s, f, tau);
  CHECK(wire.tension(s) == Approx(T).epsilon(1e-12));
  // (sheave) => T (u toward the drum + u toward the block) at the sheave point
  const Vector3 onSheave = T * (-u1 + u2), onBlock = -T * u2;
  CHECK((f.worldFrame(1).tail<3>() - onSheave).norm() < 1e-9 * T);
  CHECK((f.worldFrame(1).head<3>() - pS.cross(onSheave)).norm() < 1e-9 * T * kTop);
  CHECK((f.worldFrame(2).tail<3>() - onBlock).norm() < 1e-9 * T);
  CHECK((f.worldFrame(2).head<3>() - pB.cross(onBlock)).norm() < 1e-9 * T * kTop);
}

TEST_CASE("a block over a fixed sheave settles at T = m g with the total stretch m g L0 / EA") {
  const dynamics::Model m = verticalBlock(kMass);
  Gravity gravity("gravity", kG);
  const Vector3 drum(-20.0, 0.0, 30.0), sheave(0.0, 0.0, kTop);
  const double l1 = (sheave - drum).norm();
  RopeProperties p = rope(0.2);
  p.l0 = l1 + kL0;
  Rope wire("hoist", m, {{0, drum}, {0, sheave}, {1, kLug}}, p);
  Rig r(m, {&gravity, &wire});
  r.q[0] = HangingBlock::heightFor(kL0);
  for (int k = 0; k < 8000; ++k) r.step(1e-3);
  const Stage s = r.stage();
  CHECK(wire.tension(s) == Approx(kMass * 9.81).epsilon(1e-8));
  CHECK(wire.length(s) == Approx(l1 + kTop - kLug.z() - r.q[0]).epsilon(1e-14));
  CHECK(wire.length(s) - p.l0 == Approx(kMass * 9.81 * p.l0 / kEA).epsilon(1e-7));
}

TEST_CASE("a winch lowers or lifts a hanging block at its rate and the energy balance closes") {
  const double r = 0.083, w = kMass * 9.81;
  for (double rate : {r, -r}) {
    HangingBlock hb(rope(0.2));
    const double c = hb.wire.properties().damping;
    hb.rig.q[0] = HangingBlock::heightFor(kL0 + w * kL0 / kEA);  // static equilibrium
    hb.wire.setPayoutRate(0.0, rate);
    const Rig::Balance bal = hb.rig.energyBalance(1e-3, 6000);
    // (steady state) => L0' = rate and the stretch e = (w - c e') L0 / EA grows at
    // e' = w rate / (EA + c rate): the block moves at -(rate + e'), the tension is w
    const double eDot = w * rate / (kEA + c * rate);
    INFO("rate = " << rate);
    CHECK(hb.wire.unstretchedLength(hb.rig.t) == Approx(kL0 + rate * hb.rig.t).epsilon(1e-14));
    CHECK(hb.rig.v[0] == Approx(-(rate + eDot)).epsilon(1e-6));
    CHECK(hb.wire.tension(hb.rig.stage()) == Approx(w).epsilon(1e-6));
    // (kinetic + gravity + strain energy - integral of the winch's and damper's power) => constant,
    // relative to the work of gravity over the run
    const double scale = w * r * hb.rig.t;
    CHECK(bal.maxError / scale < 1e-6);
    CHECK(bal.maxWork > 0.01 * scale);  // the winch term is really in the balance
  }
}

TEST_CASE("the breaking load is exceeded when the tension at a stage passes it") {
  const double w = kMass * 9.81;
  for (double mbl : {0.9 * w, 1.1 * w}) {
    RopeProperties p = rope(0.0);
    p.breakingLoad = mbl;
    HangingBlock hb(p);
    hb.rig.q[0] = HangingBlock::heightFor(kL0 + w * kL0 / kEA);
    CHECK(hb.wire.exceedsBreakingLoad(hb.rig.stage()) == (mbl < w));
    hb.rig.step(1e-3);
    CHECK(hb.wire.exceedsBreakingLoad(hb.rig.stage()) == (mbl < w));
  }
  HangingBlock none(rope(0.0));
  none.rig.q[0] = HangingBlock::heightFor(2.0 * kL0);
  CHECK(none.wire.tension(none.rig.stage()) > 1e8);
  CHECK_FALSE(none.wire.exceedsBreakingLoad(none.rig.stage()));
}

TEST_CASE("bad parameters and a non-finite state are refused naming the rope") {
  const dynamics::Model m = verticalBlock(kMass);
  const std::vector<Attachment> path{{0, Vector3(0.0, 0.0, kTop)}, {1, kLug}};
  RopeProperties p = rope(0.1);
  p.ea = std::nan("");
  CHECK_THROWS_WITH(Rope("hoist-7", m, path, p), Contains("hoist-7") && Contains("EA"));
  p = rope(0.1);
  p.l0 = -1.0;
  CHECK_THROWS_AS(Rope("hoist-7", m, path, p), std::invalid_argument);
  p = rope(0.1);
  p.damping = -1.0;
  CHECK_THROWS_AS(Rope("hoist-7", m, path, p), std::invalid_argument);
  p = rope(0.1);
  p.breakingLoad = 0.0;
  CHECK_THROWS_AS(Rope("hoist-7", m, path, p), std::invalid_argument);
  CHECK_THROWS_WITH(Rope("hoist-7", m, path, rope(0.1), 0),
                    Contains("hoist-7") && Contains("parts"));
  CHECK_THROWS_WITH(Rope("hoist-7", m, {{0, Vector3::Zero()}, {2, kLug}}, rope(0.1)),
                    Contains("hoist-7"));
  // (NaN position) => evaluate throws ForceError naming the provider and the body
  Rope wire("hoist-7", m, path, rope(0.1));
  Rig r(m, {&wire});
  r.q[0] = std::nan("");
  CHECK_THROWS_AS(evaluate(wire, r.stage()), ForceError);
  CHECK_THROWS_WITH(evaluate(wire, r.stage()), Contains("hoist-7") && Contains("block"));
  // (set-points in the past) => refused
  wire.setPayoutRate(2.0, 0.1);
  CHECK_THROWS_AS(wire.setPayoutRate(1.0, 0.1), std::invalid_argument);
}
