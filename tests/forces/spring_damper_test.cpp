// The translational spring-damper: the period sqrt(m/k) of a block it pushes and pulls, the
// damped decay against the closed form, a bumper stop's contact time and rebound, the forces on
// two bodies equal and opposite, and the energy balance with a table, preload, stops and damping.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "force_rig.hpp"
#include "forces/spring_damper.hpp"

using namespace yardsim;
using namespace yardsim::forces;
using namespace yardsim::forces::testing;

namespace {
constexpr double kMass = 1000.0;  // kg
constexpr double kK = 4.0e4;      // N/m
constexpr double kTop = 10.0;     // height of the spring's upper end, m
constexpr double kL0 = 5.0;       // free length, m

// a block on a vertical slide under a spring from the world point (0, 0, kTop) to its origin:
// L = kTop - q, equilibrium q = kTop - kL0 = 5 m
SpringDamperProperties hanging(double zeta) {
  SpringDamperProperties p;
  p.freeLength = kL0;
  p.curve = SpringCurve::linear(kK);
  p.damping = zeta * 2.0 * std::sqrt(kK * kMass);
  return p;
}
dynamics::Model twoFreeBodies() {
  dynamics::ModelBuilder b;
  b.setGravity(Vector3::Zero());
  b.addBody("a", "world", dynamics::Joint::free(), dynamics::Transform::identity(),
            dynamics::boxInertia(300.0, Vector3(2, 1, 1)));
  b.addBody("b", "world", dynamics::Joint::free(), dynamics::Transform::identity(),
            dynamics::boxInertia(500.0, Vector3(1, 3, 2)));
  return b.build();
}
}  // namespace

TEST_CASE(
    "a block on a spring oscillates at sqrt(k/m), pushed and pulled and damped as the closed form") {
  const dynamics::Model model = verticalBlock(kMass);
  const double w = std::sqrt(kK / kMass), x0 = 0.3;  // starts compressed by 0.3 m
  for (double zeta : {0.0, 0.05}) {
    SpringDamper spring("s", model, {0, Vector3(0, 0, kTop)}, {1, Vector3::Zero()}, hanging(zeta));
    Rig r(model, {&spring});
    r.q[0] = kTop - kL0 + x0;
    const double h = 2.0 * std::numbers::pi / w / 400.0;
    const double wd = w * std::sqrt(1.0 - zeta * zeta);
    double maxErr = 0.0, minForce = 0.0, maxForce = 0.0;
    for (int i = 0; i < 1200; ++i) {  // three periods
      r.step(h);
      const double x =
          x0 * std::exp(-zeta * w * r.t) *
          (std::cos(wd * r.t) + zeta / std::sqrt(1.0 - zeta * zeta) * std::sin(wd * r.t));
      maxErr = std::max(maxErr, std::abs(r.q[0] - (kTop - kL0) - x));
      const double f = spring.state(r.stage()).force;
      minForce = std::min(minForce, f);
      maxForce = std::max(maxForce, f);
    }
    CHECK(maxErr < 1e-7 * x0);
    CHECK(minForce < -0.5 * kK * x0);  // it pushed
    CHECK(maxForce > 0.5 * kK * x0);   // and pulled
  }
}

TEST_CASE("a bumper stop: contact lasts pi sqrt(m/kStop), the block rebounds with its speed") {
  const dynamics::Model model = verticalBlock(kMass);
  SpringDamperProperties p;  // no spring, a stop below 3 m
  p.freeLength = kL0;
  p.minLength = 3.0;
  p.stopStiffness = 1e6;
  SpringDamper bumper("b", model, {0, Vector3::Zero()}, {1, Vector3::Zero()}, p);
  Rig r(model, {&bumper});
  const double v0 = 2.0;
  r.q[0] = 3.5;
  r.v[0] = -v0;  // reaches the stop at t = 0.25 s
  const double h = 1e-4;
  double tOut = -1.0, deepest = 10.0;
  while (r.t < 0.6) {
    const bool inside = r.q[0] < 3.0;
    r.step(h);
    deepest = std::min(deepest, r.q[0]);
    // (leaving the stop, L = 3 again) => the time by linear interpolation inside the step
    if (inside && r.q[0] >= 3.0) tOut = r.t - (r.q[0] - 3.0) / r.v[0];
  }
  CHECK(tOut - 0.25 == Approx(std::numbers::pi * std::sqrt(kMass / 1e6)).epsilon(1e-4));
  CHECK(3.0 - deepest == Approx(v0 * std::sqrt(kMass / 1e6)).epsilon(1e-5));
  CHECK(r.v[0] == Approx(v0).epsilon(1e-6));
}

TEST_CASE("the forces on the two bodies are equal and opposite, along the line, f = k x + c L'") {
  const dynamics::Model model = twoFreeBodies();
  SpringDamperProperties p;
  p.freeLength = 2.0;
  p.curve = SpringCurve::linear(5e3);
  p.damping = 300.0;
  p.preload = 100.0;
  const Vector3 a_B(0.5, -0.2, 0.1), b_B(-0.3, 0.4, 0.2);
  SpringDamper spring("s", model, {1, a_B}, {2, b_B}, p);
  Rig r(model, {&spring});
  r.q << 0, 0, 0, std::cos(0.3), 0, std::sin(0.3), 0, 1.5, 2.0, -0.5, std::cos(0.2), std::sin(0.2),
      0, 0;
  r.v << 0.1, -0.2, 0.3, 0.5, 0.1, -0.4, -0.3, 0.2, 0.1, -0.2, 0.6, 0.3;
  const Stage s = r.stage();
  dynamics::ExternalForces f(model);
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(model.nv);
  spring.evaluate(s, f, tau);
  const dynamics::Force sum = f.worldFrame(1) + f.worldFrame(2);
  CHECK(sum.norm() < 1e-12 * f.worldFrame(1).norm());
  // by hand: the points, u, L, L' and f
  const Vector3 pA = dynamics::pointPosition(s.data, 1, a_B),
                pB = dynamics::pointPosition(s.data, 2, b_B);
  const Vector3 d = pB - pA;
  const double len = d.norm(), rate = d.dot(dynamics::pointVelocity(s.data, 2, b_B) -
                                            dynamics::pointVelocity(s.data, 1, a_B)) /
                                      len;
  const double force = 100.0 + 5e3 * (len - 2.0) + 300.0 * rate;
  CHECK((f.worldFrame(1).tail<3>() - force * d / len).norm() < 1e-10 * std::abs(force));
  CHECK((f.worldFrame(1).head<3>() - pA.cross(force * d / len)).norm() < 1e-9 * std::abs(force));
  CHECK(tau.norm() == 0.0);
}

TEST_CASE("energy balance of two tumbling bodies: linear spring, preload and damping") {
  const dynamics::Model model = twoFreeBodies();
  SpringDamperProperties p;
  p.freeLength = 2.0;
  p.curve = SpringCurve::linear(8e3);
  p.preload = -200.0;
  p.damping = 80.0;
  SpringDamper spring("s", model, {1, Vector3(0.5, -0.2, 0.1)}, {2, Vector3(-0.3, 0.4, 0.2)}, p);
  Rig r(model, {&spring});
  r.q << 0, 0, 0, 1, 0, 0, 0, 2.2, 0.3, -0.1, std::cos(0.2), std::sin(0.2), 0, 0;
  r.v << 0.4, -0.2, 0.3, -1.5, 0.1, -0.4, -0.3, 0.2, 0.6, 1.2, 0.6, 0.3;
  const Rig::Balance b = r.energyBalance(5e-4, 2000);
  CHECK(b.maxWork > 1.0);
  CHECK(b.maxError < 1e-8 * b.maxWork);
  CHECK(spring.power(r.stage()) <= 0.0);
}

TEST_CASE("energy balance with a force table and both stops converges with the step") {
  // the table's kinks and the stops cut RK4's order; a consistent V and power still make the
  // balance error vanish with the step (an inconsistent one would stall at its mismatch)
  const dynamics::Model model = twoFreeBodies();
  SpringDamperProperties p;
  p.freeLength = 2.0;
  p.curve = SpringCurve::table({-1.0, -0.2, 0.0, 0.5, 1.0}, {-4e4, -3e3, 0.0, 2e3, 1e4});
  p.preload = -200.0;
  p.damping = 80.0;
  p.minLength = 1.8;
  p.maxLength = 2.4;
  p.stopStiffness = 2e5;
  SpringDamper spring("s", model, {1, Vector3(0.5, -0.2, 0.1)}, {2, Vector3(-0.3, 0.4, 0.2)}, p);
  const auto start = [](Rig& r) {
    r.q << 0, 0, 0, 1, 0, 0, 0, 2.2, 0.3, -0.1, std::cos(0.2), std::sin(0.2), 0, 0;
    r.v << 0.4, -0.2, 0.3, -1.5, 0.1, -0.4, -0.3, 0.2, 0.6, 1.2, 0.6, 0.3;
  };
  // (the run) => both stops engage
  Rig scan(model, {&spring});
  start(scan);
  double minL = 10.0, maxL = 0.0;
  for (int i = 0; i < 2000; ++i) {
    scan.step(5e-4);
    const double len = spring.state(scan.stage()).length;
    minL = std::min(minL, len);
    maxL = std::max(maxL, len);
  }
  CHECK(minL < 1.8);
  CHECK(maxL > 2.4);
  Rig coarse(model, {&spring}), fine(model, {&spring});
  start(coarse);
  start(fine);
  const Rig::Balance bc = coarse.energyBalance(1e-3, 1000);
  const Rig::Balance bf = fine.energyBalance(1.25e-4, 8000);
  CHECK(bf.maxWork > 1.0);
  CHECK(bf.maxError < bc.maxError / 20.0);  // 8x smaller step
  CHECK(bf.maxError < 1e-5 * bf.maxWork);
}

TEST_CASE("a spring refuses bad input at the door") {
  const dynamics::Model model = verticalBlock(kMass);
  SpringDamperProperties p = hanging(0.0);
  CHECK_THROWS_AS(SpringDamper("s", model, {3, Vector3::Zero()}, {1, Vector3::Zero()}, p),
                  std::invalid_argument);
  p.damping = -1.0;
  CHECK_THROWS_AS(SpringDamper("s", model, {0, Vector3::Zero()}, {1, Vector3::Zero()}, p),
                  std::invalid_argument);
  p = hanging(0.0);
  p.minLength = 3.0;
  p.maxLength = 2.0;
  CHECK_THROWS_AS(SpringDamper("s", model, {0, Vector3::Zero()}, {1, Vector3::Zero()}, p),
                  std::invalid_argument);
}
