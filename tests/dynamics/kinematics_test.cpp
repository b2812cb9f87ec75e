// Forward kinematics against finite differences: world spatial velocity = d/dt pose, world
// spatial acceleration = d/dt world spatial velocity, and the same for points on bodies.
#include <catch2/catch.hpp>

#include <cstring>

#include "dynamics/configuration.hpp"
#include "dynamics/data.hpp"
#include "dynamics/integrators/rk4.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/rotation.hpp"
#include "test_models.hpp"

using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;

namespace {
// dv/dt = constant: moves q and v along a known second-order path
struct ConstantAcceleration final : AccelerationSource {
  Eigen::VectorXd a;
  void acceleration(double, const Eigen::VectorXd&, const Eigen::VectorXd&, Eigen::VectorXd& out) override { out = a; }
};
}  // namespace

TEST_CASE("velocities and accelerations are the time derivatives of poses and velocities") {
  std::mt19937 rng(13);
  const Model m = randomTree(rng, 10);
  Data d(m), dp(m), dm(m);
  const Eigen::VectorXd q = randomConfiguration(m, rng);
  const Eigen::VectorXd v = randomVectorX(rng, m.nv);
  ConstantAcceleration sys;
  sys.a = randomVectorX(rng, m.nv);
  forwardKinematics(m, d, q, v, sys.a);
  // (q, v, a) => states at t +- h along the path, by RK4 (exact enough for h small)
  const double h = 1e-5;
  Rk4 rk(m);
  Eigen::VectorXd qp = q, vp = v, qm = q, vm = v;
  double t = 0.0;
  rk.step(sys, t, qp, vp, h);
  rk.step(sys, t, qm, vm, -h);
  forwardKinematics(m, dp, qp, vp, sys.a);
  forwardKinematics(m, dm, qm, vm, sys.a);
  const Vector3 p_B(0.3, -0.2, 0.5);
  for (int i = 1; i < m.nbodies; ++i) {
    INFO("body " << m.names[i] << " joint " << jointTypeName(m.joints[i].type));
    // pose => world spatial velocity (omega, velocity of the body point at the world origin)
    const Motion V_W = bodyVelocityWorld(d, i);
    const Vector3 w_fd = logSO3(dp.X_WB[i].R * dm.X_WB[i].R.transpose()) / (2 * h);
    CHECK((w_fd - V_W.head<3>()).norm() < 1e-6);
    const Vector3 pd_fd = (pointPosition(dp, i, p_B) - pointPosition(dm, i, p_B)) / (2 * h);
    CHECK((pd_fd - pointVelocity(d, i, p_B)).norm() < 1e-6);
    CHECK((pointVelocity(d, i, p_B) - (V_W.tail<3>() + V_W.head<3>().cross(pointPosition(d, i, p_B)))).norm() < 1e-12);
    // world spatial velocity => world spatial acceleration
    const Motion A_fd = (bodyVelocityWorld(dp, i) - bodyVelocityWorld(dm, i)) / (2 * h);
    CHECK((A_fd - bodyAccelerationWorld(d, i)).norm() < 1e-5);
    const Vector3 pa_fd = (pointVelocity(dp, i, p_B) - pointVelocity(dm, i, p_B)) / (2 * h);
    CHECK((pa_fd - pointAcceleration(d, i, p_B)).norm() < 1e-5);
  }
}

TEST_CASE("a planar chain stretched along x puts link k at x = k — Euler angles of a rotated link") {
  const Model m = planarChain(4);
  Data d(m);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(4);
  forwardKinematics(m, d, q);
  for (int i = 1; i <= 4; ++i) CHECK((pointPosition(d, i, Vector3::Zero()) - Vector3(i - 1, 0, 0)).norm() < 1e-15);
  q << 0.5, 0.0, 0.0, 0.0;  // about +y: the chain dips below the x axis (z < 0), pitch = 0.5
  forwardKinematics(m, d, q);
  CHECK(pointPosition(d, 4, Vector3(1, 0, 0)).z() == Approx(-4.0 * std::sin(0.5)));
  const Vector3 e = bodyEulerAngles(d, 4);
  CHECK(e.x() == Approx(0.0).margin(1e-14));
  CHECK(e.y() == Approx(0.5));
  CHECK(e.z() == Approx(0.0).margin(1e-14));
}

TEST_CASE("the coordinate-axis placement and subspace equal the general joint formulas") {
  // (special-cased joints) => X_PB bit for bit as X_PJ * jointTransform; R_WB and X_WB S equal to
  // the general products but for the sign of exact zeros
  std::mt19937 rng(22);
  const Model m = randomAxisTree(rng, 30);
  Data d(m);
  int special = 0;
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::VectorXd q = randomConfiguration(m, rng);
    if (trial == 0) q.tail(m.nq - 7).setZero();
    if (trial == 1) q.tail(m.nq - 7).setConstant(-0.0);
    forwardKinematics(m, d, q);
    for (int i = 1; i < m.nbodies; ++i) {
      const Joint& j = m.joints[i];
      const Transform X_JC = jointTransform(j, q.data() + m.idxQ[i]);
      const Transform ref{X_JC.R, m.X_PJ[i].p + X_JC.p};
      CHECK(std::memcmp(d.X_PB[i].R.data(), ref.R.data(), sizeof(double) * 9) == 0);
      CHECK(std::memcmp(d.X_PB[i].p.data(), ref.p.data(), sizeof(double) * 3) == 0);
      const Transform refW = d.X_WB[m.parent[i]] * d.X_PB[i];
      CHECK((d.X_WB[i].R.array() == refW.R.array()).all());
      CHECK(std::memcmp(d.X_WB[i].p.data(), refW.p.data(), sizeof(double) * 3) == 0);
      if (m.jointNv[i] != 1) continue;
      special += m.jointAxis[i] >= 0;
      const Motion s = worldSubspaceColumn(m, d, i);
      const Motion sRef = d.X_WB[i].actMotion(d.S[i].col(0));
      CHECK((s.array() == sRef.array()).all());
    }
  }
  CHECK(special == 20 * 22);  // bodies 1-29 but the negative axes (3, 7, ..., 27)
}
