#include "dynamics/loop_constraints.hpp"

#include "dynamics/kinematics.hpp"
#include "dynamics/rotation.hpp"

namespace yardsim::dynamics {

namespace {

// (6-vector e, mask) => the selected rows written at out[row...]
template <class Out>
void scatter(const Vector6& e, std::uint8_t mask, Out&& out) {
  int r = 0;
  for (int k = 0; k < 6; ++k) {
    if (mask & (1u << k)) out(r++) = e[k];
  }
}

// (q) => X_WB and S_W for every body
void worldSubspaces(const Model& m, Data& d, const Eigen::VectorXd& q) {
  forwardKinematics(m, d, q);
  for (int i = 1; i < m.nbodies; ++i) {
    for (int k = 0; k < m.jointNv[i]; ++k) d.S_W.col(m.idxV[i] + k) = d.X_WB[i].actMotion(d.S[i].col(k));
  }
}

// (S_W, loop) => rows of J for that loop
void fillJacobian(const Model& m, Data& d, const LoopConstraint& c) {
  const Transform X_WF = d.X_WB[c.bodyA] * c.X_AF;
  const Vector3 p_G = d.X_WB[c.bodyB].actPoint(c.X_BG.p);
  const Matrix3 Rt = X_WF.R.transpose();
  auto rows = d.J.middleRows(c.row, c.dim);
  rows.setZero();
  auto add = [&](int body, double sign) {
    for (int j = body; j > 0; j = m.parent[j]) {
      for (int k = 0; k < m.jointNv[j]; ++k) {
        const int col = m.idxV[j] + k;
        const Motion s = d.S_W.col(col);
        Vector6 e;
        e.head<3>() = Rt * s.head<3>();
        e.tail<3>() = Rt * (s.tail<3>() + s.head<3>().cross(p_G));
        int r = 0;
        for (int b = 0; b < 6; ++b) {
          if (c.mask & (1u << b)) rows(r++, col) += sign * e[b];
        }
      }
    }
  };
  add(c.bodyB, 1.0);
  add(c.bodyA, -1.0);
}

}  // namespace

const Eigen::VectorXd& loopResidual(const Model& m, Data& d, const Eigen::VectorXd& q) {
  forwardKinematics(m, d, q);
  for (const LoopConstraint& c : m.loops) {
    // (X_WA, X_WB) => X_FG => [rotation error; p_FG]
    const Transform X_FG = (d.X_WB[c.bodyA] * c.X_AF).inverse() * (d.X_WB[c.bodyB] * c.X_BG);
    Vector6 e;
    if ((c.mask & 7) == 7) {
      e.head<3>() = logSO3(X_FG.R);
    } else {
      e.head<3>() = Vector3(-X_FG.R(1, 2), X_FG.R(0, 2), 0.0);
    }
    e.tail<3>() = X_FG.p;
    scatter(e, c.mask, [&](int r) -> double& { return d.residual[c.row + r]; });
  }
  return d.residual;
}

double loopResidualNorm(const Model& m, Data& d, const Eigen::VectorXd& q) {
  if (m.nc == 0) return 0.0;
  return loopResidual(m, d, q).cwiseAbs().maxCoeff();
}

const Eigen::MatrixXd& loopJacobian(const Model& m, Data& d, const Eigen::VectorXd& q) {
  worldSubspaces(m, d, q);
  for (const LoopConstraint& c : m.loops) fillJacobian(m, d, c);
  return d.J;
}

void loopJacobianAndBias(const Model& m, Data& d, const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
  // (q, v, ddq = 0) => X_WB, V, A (bias accelerations, no gravity), then world frame copies
  d.dv.setZero();
  forwardKinematics(m, d, q, v, d.dv);
  for (int i = 1; i < m.nbodies; ++i) {
    for (int k = 0; k < m.jointNv[i]; ++k) d.S_W.col(m.idxV[i] + k) = d.X_WB[i].actMotion(d.S[i].col(k));
    d.V_W[i] = d.X_WB[i].actMotion(d.V_B[i]);
    d.A0_W[i] = d.X_WB[i].actMotion(d.A_B[i]);
  }
  for (const LoopConstraint& c : m.loops) {
    fillJacobian(m, d, c);
    // (V_W, A0_W of A and B, point G) => kappa = d/dt(J v) at ddq = 0
    const Transform X_WF = d.X_WB[c.bodyA] * c.X_AF;
    const Matrix3 Rt = X_WF.R.transpose();
    const Vector3 p_G = d.X_WB[c.bodyB].actPoint(c.X_BG.p);
    const Vector3 wA = d.V_W[c.bodyA].head<3>(), vA = d.V_W[c.bodyA].tail<3>();
    const Vector3 wB = d.V_W[c.bodyB].head<3>(), vB = d.V_W[c.bodyB].tail<3>();
    const Vector3 alA = d.A0_W[c.bodyA].head<3>(), aA = d.A0_W[c.bodyA].tail<3>();
    const Vector3 alB = d.A0_W[c.bodyB].head<3>(), aB = d.A0_W[c.bodyB].tail<3>();
    const Vector3 pdotG = vB + wB.cross(p_G);
    const Vector3 u = pdotG - (vA + wA.cross(p_G));
    const Vector3 wrel = wB - wA;
    Vector6 e;
    e.head<3>() = Rt * (alB - alA - wA.cross(wrel));
    e.tail<3>() = Rt * ((aB + alB.cross(p_G)) - (aA + alA.cross(p_G)) + wrel.cross(pdotG) - wA.cross(u));
    scatter(e, c.mask, [&](int r) -> double& { return d.kappa[c.row + r]; });
  }
  d.cv.noalias() = d.J * v;
}

}  // namespace yardsim::dynamics
