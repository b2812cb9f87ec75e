// Closed-loop forward dynamics: a pendulum made of a free body and a revolute cut moves exactly
// like the revolute pendulum; a parallelogram's coupler keeps its orientation; the four-bar and
// the slider-crank stay closed (with projection) and follow their closed-form kinematics; a weld
// to the world holds a body still; Baumgarte keeps the drift bounded without projection.
#include <catch2/catch.hpp>

#include "dynamics/aba.hpp"
#include "dynamics/configuration.hpp"
#include "dynamics/constrained_dynamics.hpp"
#include "dynamics/energy.hpp"
#include "dynamics/integrators/rk4.hpp"
#include "dynamics/loop_constraints.hpp"
#include "dynamics/multibody_system.hpp"
#include "dynamics/projection.hpp"
#include "dynamics/rotation.hpp"
#include "test_mechanisms.hpp"
#include "test_models.hpp"

using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;

TEST_CASE("without loops, the Schur-complement forward dynamics equals ABA") {
  std::mt19937 rng(27);
  const Model m = randomTree(rng, 11);
  Data d(m), d2(m);
  const Eigen::VectorXd q = randomConfiguration(m, rng), v = randomVectorX(rng, m.nv), tau = randomVectorX(rng, m.nv);
  CHECK(relativeError(constrainedForwardDynamics(m, d, q, v, tau), aba(m, d2, q, v, tau)) < 1e-10);
}

TEST_CASE("a free body held by a revolute cut to the world swings like a revolute pendulum") {
  ModelBuilder rb, cb;
  rb.setGravity(Vector3(0, -9.81, 0));
  cb.setGravity(Vector3(0, -9.81, 0));
  rb.addBody("rod", "world", Joint::revolute(), {}, rodInertia(1.0, 1.0));
  cb.addBody("rod", "world", Joint::free(), {}, rodInertia(1.0, 1.0));
  cb.addLoop("pin", "world", {}, "rod", {}, kAxisConstraint);
  const Model mr = rb.build(), mc = cb.build();
  MultibodySystem sr(mr), sc(mc);
  sc.setProjection(true);
  Rk4 rr(mr), rc(mc);
  const double th0 = 0.4;
  Eigen::VectorXd qr(1), vr(1), qc(7), vc = Eigen::VectorXd::Zero(6);
  qr << th0;
  vr << 0.5;
  qc << 0, 0, 0, std::cos(th0 / 2), 0, 0, std::sin(th0 / 2);
  vc[2] = 0.5;
  double tr = 0.0, tc = 0.0, err = 0.0;
  Data d(mc);
  for (int k = 0; k < 2000; ++k) {
    rr.step(sr, tr, qr, vr, 1e-3);
    rc.step(sc, tc, qc, vc, 1e-3);
    const double angle = 2.0 * std::atan2(qc[6], qc[3]);
    err = std::max(err, std::abs(std::remainder(angle - qr[0], 2 * M_PI)));
    CHECK(loopResidualNorm(mc, d, qc) < 1e-10);
  }
  CHECK(err < 1e-9);
  // the multipliers are the pin force: at rest at the bottom it carries the weight
  Eigen::VectorXd qb(7), vb = Eigen::VectorXd::Zero(6);
  qb << 0, 0, 0, std::cos(-M_PI / 4), 0, 0, std::sin(-M_PI / 4);  // hanging straight down
  constrainedForwardDynamics(mc, d, qb, vb, Eigen::VectorXd::Zero(6));
  CHECK(d.ddq.norm() < 1e-12);
  CHECK((d.J.transpose() * d.lambda - d.nle).norm() < 1e-9);
  // the pin force on the rod is its weight, upwards, in the pin's translation rows (F = world frame)
  CHECK(std::abs(d.lambda[2]) < 1e-9);
  CHECK(d.lambda[3] == Approx(9.81));
}

TEST_CASE("a parallelogram four-bar: the coupler keeps its orientation and the rocker follows the crank") {
  const FourBar fb = makeFourBar(1.0, 2.0, 1.0, 2.0);
  MultibodySystem sys(fb.model);
  sys.setProjection(true);
  Rk4 rk(fb.model);
  const double th0 = -M_PI / 2 + 0.5;
  Eigen::VectorXd q(3), v = Eigen::VectorXd::Zero(3);
  q << th0, -th0, th0;
  Data d(fb.model);
  REQUIRE(loopResidualNorm(fb.model, d, q) < 1e-15);
  double t = 0.0, orient = 0.0, follow = 0.0;
  for (int k = 0; k < 3000; ++k) {
    rk.step(sys, t, q, v, 1e-3);
    orient = std::max(orient, std::abs(q[0] + q[1]));
    follow = std::max(follow, std::abs(q[2] - q[0]));
  }
  CHECK(orient < 1e-10);
  CHECK(follow < 1e-10);
  CHECK(std::abs(q[0] + M_PI / 2) <= 0.5 + 1e-6);  // it swings within its initial amplitude
}

TEST_CASE("a four-bar stays closed with projection, conserves energy, and matches its closed-form branch") {
  const FourBar fb = makeFourBar(1.0, 3.0, 2.5, 3.0);
  Data d(fb.model);
  MultibodySystem sys(fb.model);
  sys.setProjection(true);
  Rk4 rk(fb.model);
  Eigen::VectorXd q = fb.closedConfiguration(1.0), v = Eigen::VectorXd::Zero(3);
  v[0] = 3.0;  // a consistent velocity: project a crank speed onto J v = 0
  projectVelocities(fb.model, d, q, v);
  const double E0 = kineticEnergy(fb.model, d, q, v) + potentialEnergy(fb.model, d, q);
  double t = 0.0, res = 0.0, branch = 0.0, energy = 0.0;
  for (int k = 0; k < 3000; ++k) {
    rk.step(sys, t, q, v, 1e-3);
    res = std::max(res, loopResidualNorm(fb.model, d, q));
    const Eigen::VectorXd closed = fb.closedConfiguration(q[0]);
    branch = std::max(branch, std::abs(std::remainder(q[1] - closed[1], 2 * M_PI)) + std::abs(std::remainder(q[2] - closed[2], 2 * M_PI)));
    energy = std::max(energy, std::abs(kineticEnergy(fb.model, d, q, v) + potentialEnergy(fb.model, d, q) - E0) / std::abs(E0));
  }
  INFO("residual " << res << " branch " << branch << " energy " << energy);
  CHECK(res <= 1e-10);
  CHECK(branch < 1e-10);
  CHECK(energy < 1e-7);
}

TEST_CASE("a slider-crank stays closed and its slider follows r cos(theta) + sqrt(l^2 - r^2 sin^2(theta))") {
  const SliderCrank sc = makeSliderCrank(0.5, 1.5);
  Data d(sc.model);
  MultibodySystem sys(sc.model);
  sys.setProjection(true);
  sys.setForces([](double, const Eigen::VectorXd&, const Eigen::VectorXd&, const Data&, ExternalForces&, Eigen::VectorXd& tau) {
    tau[0] = 20.0;  // driving torque on the crank
  });
  Rk4 rk(sc.model);
  Eigen::VectorXd q = sc.closedConfiguration(0.3), v = Eigen::VectorXd::Zero(3);
  REQUIRE(loopResidualNorm(sc.model, d, q) < 1e-14);
  double t = 0.0, res = 0.0, kin = 0.0;
  for (int k = 0; k < 2000; ++k) {
    rk.step(sys, t, q, v, 1e-3);
    res = std::max(res, loopResidualNorm(sc.model, d, q));
    kin = std::max(kin, std::abs(q[2] - sc.sliderPosition(q[0])));
  }
  CHECK(q[0] > 2 * M_PI);  // driven through full turns
  CHECK(res <= 1e-10);
  CHECK(kin < 1e-10);
}

TEST_CASE("a weld to the world holds a body: its joint accelerations vanish") {
  std::mt19937 rng(28);
  ModelBuilder b;
  b.addBody("hull", "world", Joint::free(), {}, randomInertia(rng));
  b.addBody("crane", "hull", Joint::revolute(Vector3::UnitZ()), Transform::translation(Vector3(1, 0, 0)), randomInertia(rng));
  b.addLoop("moored", "world", {}, "hull", {}, kWeldConstraint);
  const Model m = b.build();
  Data d(m);
  Eigen::VectorXd q = neutralConfiguration(m), v = Eigen::VectorXd::Zero(7);
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(7);
  tau[6] = 3.0;
  constrainedForwardDynamics(m, d, q, v, tau);
  CHECK(d.ddq.head<6>().norm() < 1e-12);
  // the crane turns as if on a fixed base: I_zz about its joint
  const SpatialInertia& I = m.inertias[2];
  const double Izz = I.inertiaCom(2, 2) + I.mass * (I.com.x() * I.com.x() + I.com.y() * I.com.y());
  CHECK(d.ddq[6] == Approx(3.0 / Izz).epsilon(1e-10));
}

TEST_CASE("Baumgarte stabilisation keeps the four-bar's drift small without projection") {
  const FourBar fb = makeFourBar(1.0, 3.0, 2.5, 3.0);
  Data d(fb.model);
  auto run = [&](Baumgarte stab) {
    MultibodySystem sys(fb.model);
    sys.setBaumgarte(stab);
    Rk4 rk(fb.model);
    Eigen::VectorXd q = fb.closedConfiguration(1.0), v = Eigen::VectorXd::Zero(3);
    q[2] += 1e-3;  // start slightly open
    double t = 0.0;
    for (int k = 0; k < 2000; ++k) rk.step(sys, t, q, v, 1e-3);
    return loopResidualNorm(fb.model, d, q);
  };
  const double free = run({});
  const double stabilised = run({20.0, 20.0});
  INFO(free << " " << stabilised);
  CHECK(stabilised < 1e-6);
  CHECK(stabilised < 1e-3 * free);
}

TEST_CASE("a planar four-bar moves the same whether closed by a 3-D revolute cut or a planar point cut") {
  // the revolute cut has three redundant rows (out of plane), which the Schur solve must drop
  const FourBar axis = makeFourBar(1.0, 3.0, 2.5, 3.0, kAxisConstraint);
  const FourBar planar = makeFourBar(1.0, 3.0, 2.5, 3.0, kPlanarPointConstraint);
  MultibodySystem sa(axis.model), sp(planar.model);
  Rk4 ra(axis.model), rp(planar.model);
  Eigen::VectorXd qa = axis.closedConfiguration(1.0), va = Eigen::VectorXd::Zero(3);
  Eigen::VectorXd qp = qa, vp = va;
  double ta = 0.0, tp = 0.0, diff = 0.0;
  for (int k = 0; k < 1000; ++k) {
    ra.step(sa, ta, qa, va, 1e-3);
    rp.step(sp, tp, qp, vp, 1e-3);
    diff = std::max(diff, (qa - qp).cwiseAbs().maxCoeff());
  }
  CHECK(sa.data().schurRank == 2);
  CHECK(sp.data().schurRank == 2);
  CHECK(diff < 1e-12);
}
