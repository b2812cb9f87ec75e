// Loop constraints: closed-form residuals of the four-bar, the Jacobian as the derivative of the
// residual, and kappa as the derivative of J v along a path.
#include <catch2/catch.hpp>

#include "dynamics/configuration.hpp"
#include "dynamics/integrators/rk4.hpp"
#include "dynamics/loop_constraints.hpp"
#include "dynamics/projection.hpp"
#include "test_mechanisms.hpp"
#include "test_models.hpp"

using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;

namespace {
struct ConstantAcceleration final : AccelerationSource {
  Eigen::VectorXd a;
  void acceleration(double, const Eigen::VectorXd&, const Eigen::VectorXd&, Eigen::VectorXd& out) override { out = a; }
};

Model treeWithLoops(std::mt19937& rng) {
  ModelBuilder b;
  const auto& types = allJointTypes();
  for (int i = 0; i < 9; ++i) {
    const std::string parent = i < 2 ? "world" : indexed("b", i % 3 == 0 ? i - 2 : i - 1);
    b.addBody(indexed("b", i), parent, jointOfType(i == 0 ? JointType::Free : types[(i - 1) % types.size()], rng),
              Transform{randomRotation(rng), randomVector(rng)}, randomInertia(rng));
  }
  const std::uint8_t masks[] = {kPointConstraint, kAxisConstraint, kCylinderConstraint, kWeldConstraint,
                                kPlanarPointConstraint};
  int k = 0;
  for (auto [a, c] : {std::pair{"b8", "b3"}, {"b5", "world"}, {"b2", "b7"}, {"world", "b4"}, {"b1", "b6"}}) {
    b.addLoop(indexed("l", k), a, Transform{randomRotation(rng), randomVector(rng)}, c,
              Transform{randomRotation(rng), randomVector(rng)}, masks[k]);
    ++k;
  }
  return b.build();
}
}  // namespace

TEST_CASE("the four-bar's closed-form configuration has zero residual, an open one does not") {
  const FourBar fb = makeFourBar(1.0, 3.0, 2.5, 3.0);
  Data d(fb.model);
  for (double th : {0.0, 0.7, 2.0, -1.3}) {
    CHECK(loopResidualNorm(fb.model, d, fb.closedConfiguration(th)) < 1e-14);
  }
  Eigen::VectorXd q = fb.closedConfiguration(0.7);
  q[2] += 0.01;
  const Eigen::VectorXd& r = loopResidual(fb.model, d, q);
  CHECK(r.size() == 5);
  // rows: rot x, rot y, trans x, trans y, trans z; the rocker tip moved by 2.5 * 0.01 in the plane
  CHECK(r.head<2>().norm() < 1e-15);
  CHECK(std::abs(r[4]) < 1e-15);
  CHECK(r.segment<2>(2).norm() == Approx(2.5 * 2 * std::sin(0.005)).epsilon(1e-12));
}

TEST_CASE("J v is the time derivative of translational residuals everywhere, and of all on the manifold") {
  std::mt19937 rng(25);
  // point constraints: exact off the manifold
  ModelBuilder b;
  for (int i = 0; i < 6; ++i) {
    b.addBody(indexed("b", i), i == 0 ? "world" : indexed("b", i - 1),
              jointOfType(allJointTypes()[i % 7], rng), Transform{randomRotation(rng), randomVector(rng)}, randomInertia(rng));
  }
  b.addLoop("p", "b5", Transform{randomRotation(rng), randomVector(rng)}, "b1", Transform{randomRotation(rng), randomVector(rng)},
            kPointConstraint);
  b.addLoop("q", "world", Transform{randomRotation(rng), randomVector(rng)}, "b3", Transform{randomRotation(rng), randomVector(rng)},
            kPlanarPointConstraint);
  const Model m = b.build();
  Data d(m);
  const Eigen::VectorXd q = randomConfiguration(m, rng), v = randomVectorX(rng, m.nv);
  const double h = 1e-6;
  Eigen::VectorXd qp(m.nq), qm(m.nq);
  integrate(m, q, v, h, qp);
  integrate(m, q, v, -h, qm);
  const Eigen::VectorXd fd = (Eigen::VectorXd(loopResidual(m, d, qp)) - Eigen::VectorXd(loopResidual(m, d, qm))) / (2 * h);
  loopJacobian(m, d, q);
  CHECK((d.J * v - fd).norm() < 1e-7);
  // every constraint kind, on the manifold: the four-bar with a weld-free axis cut
  const FourBar fb = makeFourBar(1.0, 3.0, 2.5, 3.0);
  Data df(fb.model);
  const Eigen::VectorXd qf = fb.closedConfiguration(0.9);
  loopJacobian(fb.model, df, qf);
  const double th = 1e-6;
  const Eigen::VectorXd dq = (fb.closedConfiguration(0.9 + th) - fb.closedConfiguration(0.9 - th)) / (2 * th);
  CHECK((df.J * dq).norm() < 1e-8);  // the tangent of the closed branch satisfies J dq = 0
}

TEST_CASE("kappa is d/dt (J v) - J a for every constraint kind") {
  std::mt19937 rng(26);
  const Model m = treeWithLoops(rng);
  Data d(m), dp(m), dm(m);
  ConstantAcceleration sys;
  sys.a = randomVectorX(rng, m.nv);
  const Eigen::VectorXd q = randomConfiguration(m, rng), v = randomVectorX(rng, m.nv);
  Rk4 rk(m);
  const double h = 1e-5;
  Eigen::VectorXd qp = q, vp = v, qm = q, vm = v;
  double t = 0.0;
  rk.step(sys, t, qp, vp, h);
  rk.step(sys, t, qm, vm, -h);
  loopJacobianAndBias(m, d, q, v);
  loopJacobianAndBias(m, dp, qp, vp);
  loopJacobianAndBias(m, dm, qm, vm);
  const Eigen::VectorXd fd = (dp.cv - dm.cv) / (2 * h);
  CHECK(relativeError(d.J * sys.a + d.kappa, fd) < 1e-7);
  CHECK((d.cv - d.J * v).norm() < 1e-14);
}
