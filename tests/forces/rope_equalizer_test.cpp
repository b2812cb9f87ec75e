// The equalizer: an unevenly loaded beam hanging from two branches over one equalizing sheave
// comes to rest with its centre of mass under the sheave, equal branch tensions whose vertical
// sum is the weight, branches at equal angles to the vertical, and the total length stretched
// by T L0 / EA; the energy balance closes; k = 3 branches with one over a sheave on a body.
#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

#include "dynamics/rotation.hpp"
#include "force_rig.hpp"
#include "forces/rope.hpp"
#include "forces/gravity.hpp"

using namespace yardsim;
using namespace yardsim::forces;
using namespace yardsim::forces::testing;
using Catch::Matchers::Contains;

namespace {

const Vector3 kG(0.0, 0.0, -9.81);
constexpr double kMass = 200e3;  // kg
constexpr double kEA = 1e9;      // N
const Vector3 kSheave(0.0, 0.0, 20.0);
const Vector3 kLugA(-3.0, 0.0, 0.0), kLugB(3.0, 0.0, 0.0);  // on the beam
const Vector3 kCom(1.0, 0.0, -0.5);                         // off-centre, below the lugs

dynamics::Model beam() {
  dynamics::ModelBuilder b;
  b.setGravity(Vector3::Zero());
  b.addBody("beam", "world", dynamics::Joint::free(), dynamics::Transform::identity(),
            dynamics::makeInertia(kMass, kCom,
                                  dynamics::boxInertia(kMass, Vector3(8.0, 2.0, 1.0)).inertiaCom));
  return b.build();
}

// A test-only viscous damper on one body: -c v at the centre of mass and -c_r omega, so that
// the swinging modes (which do not change the rope's length) come to rest too.
class Damper final : public ForceProvider {
 public:
  Damper(double c, double cr) : ForceProvider("damper"), c_(c), cr_(cr) {}

 protected:
  void doEvaluate(const Stage& s, dynamics::ExternalForces& f, Eigen::VectorXd&) const override {
    const Vector3 com = s.model.inertias[1].com;
    f.addPointForceWorld(1, dynamics::pointPosition(s.data, 1, com),
                         -c_ * dynamics::pointVelocity(s.data, 1, com));
    dynamics::Force M = dynamics::Force::Zero();
    M.head<3>() = -cr_ * omega(s);
    f.addWorldFrame(1, M);
  }
  double doPower(const Stage& s) const override {
    const Vector3 v = dynamics::pointVelocity(s.data, 1, s.model.inertias[1].com);
    return -c_ * v.squaredNorm() - cr_ * omega(s).squaredNorm();
  }

 private:
  static Vector3 omega(const Stage& s) { return s.data.X_WB[1].R * s.data.V_B[1].head<3>(); }
  double c_, cr_;
};

}  // namespace

TEST_CASE("an uneven load rests on an equalizer with equal tensions carrying its weight") {
  const dynamics::Model m = beam();
  Gravity gravity("gravity", kG);
  // (level beam 8 m under the sheave) => both branches sqrt(3^2 + 8^2), the rope just straight
  const double zBeam = 12.0, l0 = 2.0 * std::hypot(3.0, 8.0);
  RopeProperties p;
  p.ea = kEA;
  p.l0 = l0;
  p.damping = 1e6;
  Rope eq("equalizer", m, {0, kSheave}, {{{1, kLugA}}, {{1, kLugB}}}, p);
  Damper damper(2.0 * kMass, 2.0 * kMass * 10.0);
  Rig r(m, {&gravity, &eq, &damper});
  r.q << 0.0, 0.0, zBeam, 1.0, 0.0, 0.0, 0.0;
  const Rig::Balance bal =
      r.energyBalance(1e-3, 44000);  // the slowest (overdamped) mode decays as e^(-0.6 t)
  const Stage s = r.stage();
  CHECK(r.v.norm() < 1e-7);
  // (statics) => the centre of mass hangs under the sheave: the rope forces meet there
  const Vector3 c_W = dynamics::pointPosition(s.data, 1, kCom);
  CHECK(std::abs(c_W.x() - kSheave.x()) < 1e-7);
  CHECK(std::abs(c_W.y() - kSheave.y()) < 1e-7);
  // (the load is uneven) => the beam tilts and the branches differ in length
  const double lA = eq.branchLength(s, 0), lB = eq.branchLength(s, 1);
  CHECK(std::abs(lA - lB) > 0.5);
  // (one tension T in both branches) => vertical sum = weight, horizontal sum = 0, equal angles
  const double T = eq.tension(s);
  const Vector3 pA = dynamics::pointPosition(s.data, 1, kLugA),
                pB = dynamics::pointPosition(s.data, 1, kLugB);
  const Vector3 fA = T * (kSheave - pA) / (kSheave - pA).norm(),
                fB = T * (kSheave - pB) / (kSheave - pB).norm();
  CHECK(fA.z() + fB.z() == Approx(kMass * 9.81).epsilon(1e-7));
  CHECK(std::abs(fA.x() + fB.x()) < 1e-7 * kMass * 9.81);
  CHECK(fA.z() / fA.norm() == Approx(fB.z() / fB.norm()).epsilon(1e-7));
  {  // (evaluate at the same stage) => the block feels the two branches' pull, T each
    dynamics::ExternalForces f(s.model);
    Eigen::VectorXd tau = Eigen::VectorXd::Zero(s.model.nv);
    eq.evaluate(s, f, tau);
    CHECK(f.worldFrame(1)[5] == Approx(fA.z() + fB.z()).epsilon(1e-12));
  }
  CHECK_FALSE(eq.exceedsBreakingLoad(s));  // no breaking load given
  CHECK(eq.branchLength(s, 0) == Approx((kSheave - pA).norm()).epsilon(1e-14));
  // (rope law) => total length L0 + T / (EA / L0), and the sum of the branches
  CHECK(eq.length(s) == Approx(lA + lB).epsilon(1e-14));
  CHECK(eq.length(s) == Approx(l0 + T / (kEA / l0)).epsilon(1e-9));
  // (energy) => kinetic + gravity + strain - integral of damping power constant
  CHECK(bal.maxError / (kMass * 9.81 * 1.0) < 1e-6);
}

TEST_CASE("an undamped equalizer conserves kinetic plus potential energy") {
  const dynamics::Model m = beam();
  Gravity gravity("gravity", kG);
  RopeProperties p;
  p.ea = kEA;
  p.l0 = 2.0 * std::hypot(3.0, 8.0) - 0.01;  // a little stretched at the start
  Rope eq("equalizer", m, {0, kSheave}, {{{1, kLugA}}, {{1, kLugB}}}, p);
  Rig r(m, {&gravity, &eq});
  r.q << 0.0, 0.0, 12.0, 1.0, 0.0, 0.0, 0.0;
  r.v << 0.1, -0.2, 0.05, 0.3, 0.0, 0.0;
  const double e0 = r.energy();
  double drift = 0.0;
  for (int k = 0; k < 3000; ++k) {
    r.step(5e-4);
    drift = std::max(drift, std::abs(r.energy() - e0));
  }
  CHECK(drift / (kMass * 9.81 * 1.0) < 1e-7);
}

TEST_CASE("three branches: the sheave body feels T times the sum of the unit vectors") {
  // the equalizing sheave on a hook block (body 1); branch 2 runs over a sheave on the load (body
  // 2)
  dynamics::ModelBuilder b;
  b.setGravity(Vector3::Zero());
  b.addBody("hook", "world", dynamics::Joint::free(), dynamics::Transform::identity(),
            dynamics::boxInertia(5e3, Vector3(1, 1, 1)));
  b.addBody("load", "world", dynamics::Joint::free(), dynamics::Transform::identity(),
            dynamics::boxInertia(kMass, Vector3(6, 4, 2)));
  const dynamics::Model m = b.build();
  const Vector3 sheave_H(0.0, 0.0, -0.4);
  const std::vector<std::vector<Attachment>> branches{
      {{2, Vector3(-3.0, -2.0, 1.0)}},
      {{2, Vector3(3.0, -2.0, 1.0)}},
      {{2, Vector3(0.0, 2.0, 1.0)}, {0, Vector3(0.5, 6.0, 25.0)}}};
  RopeProperties p;
  p.ea = kEA;
  p.l0 = 40.0;
  p.damping = 2e5;
  Rope eq("equalizer", m, {1, sheave_H}, branches, p);
  Rig r(m, {&eq});
  r.q << 0.3, -0.2, 20.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 5.0, 0.0, 0.0, 0.0, 0.0;
  dynamics::matrixToQuaternion(dynamics::axisRotation(Vector3(0.2, 1.0, 0.1).normalized(), 0.3),
                               r.q.data() + 3);
  dynamics::matrixToQuaternion(dynamics::axisRotation(Vector3(1.0, 0.3, 0.0).normalized(), 0.2),
                               r.q.data() + 10);
  r.v << 0.1, 0.2, -0.1, 0.5, -0.3, 0.4, 0.0, 0.1, 0.0, -0.2, 0.1, 0.3;
  const Stage s = r.stage();
  // (geometry by hand) => branch lengths, total length, tension
  const Vector3 pS = dynamics::pointPosition(s.data, 1, sheave_H);
  const Vector3 a = dynamics::pointPosition(s.data, 2, branches[0][0].p_B);
  const Vector3 bb = dynamics::pointPosition(s.data, 2, branches[1][0].p_B);
  const Vector3 c = dynamics::pointPosition(s.data, 2, branches[2][0].p_B);
  const Vector3 end = branches[2][1].p_B;
  const double L = (a - pS).norm() + (bb - pS).norm() + (c - pS).norm() + (end - c).norm();
  CHECK(eq.length(s) == Approx(L).epsilon(1e-14));
  CHECK(eq.branchLength(s, 2) == Approx((c - pS).norm() + (end - c).norm()).epsilon(1e-14));
  dynamics::ExternalForces f(m);
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(m.nv);
  eq.evaluate(s, f, tau);
  const double T = eq.tension(s);
  REQUIRE(L > p.l0);
  CHECK(T == Approx(kEA / p.l0 * (L - p.l0) + p.damping * eq.lengthRate(s)).epsilon(1e-12));
  const Vector3 onHook =
      T * ((a - pS).normalized() + (bb - pS).normalized() + (c - pS).normalized());
  CHECK((f.worldFrame(1).tail<3>() - onHook).norm() < 1e-9 * T);
  CHECK((f.worldFrame(1).head<3>() - pS.cross(onHook)).norm() < 1e-9 * T * 30.0);
  // (load) => T toward the sheave at a and b, T (u_prev + u_next) at the load's sheave c
  const Vector3 onLoad = T * ((pS - a).normalized() + (pS - bb).normalized() +
                              (pS - c).normalized() + (end - c).normalized());
  CHECK((f.worldFrame(2).tail<3>() - onLoad).norm() < 1e-9 * T);
  // (virtual work) => the forces do power -T dL/dt
  double power = 0.0;
  for (int k = 1; k < m.nbodies; ++k)
    power += f.worldFrame(k).dot(dynamics::bodyVelocityWorld(s.data, k));
  CHECK(power == Approx(-T * eq.lengthRate(s)).epsilon(1e-9));
}

TEST_CASE("an equalizer needs two branches each with an end and valid properties") {
  const dynamics::Model m = beam();
  RopeProperties p;
  p.ea = kEA;
  p.l0 = 10.0;
  CHECK_THROWS_WITH(Rope("eq-1", m, {0, kSheave}, {{{1, kLugA}}}, p), Contains("eq-1"));
  CHECK_THROWS_AS(Rope("eq-1", m, {0, kSheave}, {{{1, kLugA}}, {}}, p), std::invalid_argument);
  CHECK_THROWS_AS(Rope("eq-1", m, {0, kSheave}, {{{1, kLugA}}, {{2, kLugB}}}, p),
                  std::invalid_argument);
  p.ea = std::nan("");
  CHECK_THROWS_WITH(Rope("eq-1", m, {0, kSheave}, {{{1, kLugA}}, {{1, kLugB}}}, p),
                    Contains("eq-1") && Contains("EA"));
  // (a NaN state) => ForceError naming the equalizer
  p.ea = kEA;
  Rope eq("eq-1", m, {0, kSheave}, {{{1, kLugA}}, {{1, kLugB}}}, p);
  Rig r(m, {&eq});
  r.q[2] = std::nan("");
  dynamics::ExternalForces f(m);
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(m.nv);
  CHECK_THROWS_WITH(eq.evaluate(r.stage(), f, tau), Contains("eq-1"));
}
