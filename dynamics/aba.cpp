#include "dynamics/aba.hpp"

#include "dynamics/kinematics.hpp"

namespace yardsim::dynamics {

const Eigen::VectorXd& aba(const Model& m, Data& d, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                           const Eigen::VectorXd& tau, const ExternalForces* fext) {
  const bool world = fext != nullptr && fext->hasWorldFrame();
  // (q, v) => X_PB, V, C = c_J + V x S v_i, IA = I, pA = V x* I V - F_ext
  for (int i = 1; i < m.nbodies; ++i) {
    updateJointPlacement(m, d, i, q);
    const int p = m.parent[i];
    if (world) d.X_WB[i] = d.X_WB[p] * d.X_PB[i];
    const int nv = m.jointNv[i];
    Motion vJ;
    if (nv == 1) {
      vJ = d.S[i].col(0) * v[m.idxV[i]];
      d.C[i] = Motion::Zero();
    } else {
      vJ = d.S[i] * v.segment(m.idxV[i], nv);
      d.C[i] = jointBias(m.joints[i], q.data() + m.idxQ[i], v.data() + m.idxV[i]);
    }
    d.V[i] = d.X_PB[i].invActMotion(d.V[p]) + vJ;
    d.C[i] += crossMotion(d.V[i], vJ);
    d.IA[i] = m.inertiaMatrices[i];
    d.F[i] = crossForce(d.V[i], m.inertias[i].apply(d.V[i]));
    if (fext != nullptr) d.F[i] -= fext->inBodyFrame(d, i);
  }
  // (IA, pA) => U = IA S, D^-1, u = tau - S^T pA; articulated inertia and bias to the parent
  for (int i = m.nbodies - 1; i >= 1; --i) {
    const int nv = m.jointNv[i];
    const int p = m.parent[i];
    Matrix6 Ia;
    Force pa;
    if (nv == 1) {
      const auto s = d.S[i].col(0);
      auto U = d.U[i].col(0);
      U.noalias() = d.IA[i] * s;
      const double Dinv = 1.0 / s.dot(U);
      d.Dinv[i](0, 0) = Dinv;
      const double ui = tau[m.idxV[i]] - s.dot(d.F[i]);
      d.u[i][0] = ui;
      if (p == 0) continue;
      Ia.noalias() = d.IA[i] - (Dinv * U) * U.transpose();
      pa = d.F[i] + Ia * d.C[i] + U * (Dinv * ui);
    } else if (nv > 0) {
      d.U[i].noalias() = d.IA[i] * d.S[i];
      d.Dinv[i] = (d.S[i].transpose() * d.U[i]).inverse();
      d.u[i].noalias() = tau.segment(m.idxV[i], nv) - d.S[i].transpose() * d.F[i];
      if (p == 0) continue;
      Ia.noalias() = d.IA[i] - d.U[i] * d.Dinv[i] * d.U[i].transpose();
      pa = d.F[i] + Ia * d.C[i] + d.U[i] * (d.Dinv[i] * d.u[i]);
    } else {
      if (p == 0) continue;
      Ia = d.IA[i];
      pa = d.F[i] + Ia * d.C[i];
    }
    d.IA[p] += actInertia(d.X_PB[i], Ia);
    d.F[p] += d.X_PB[i].actForce(pa);
  }
  // (IA, pA, U, D, u) => ddq, A (including -g)
  d.A[0].head<3>().setZero();
  d.A[0].tail<3>() = -m.gravity;
  for (int i = 1; i < m.nbodies; ++i) {
    const int nv = m.jointNv[i];
    const Motion a = d.X_PB[i].invActMotion(d.A[m.parent[i]]) + d.C[i];
    if (nv == 1) {
      const auto s = d.S[i].col(0);
      const double qdd = d.Dinv[i](0, 0) * (d.u[i][0] - d.U[i].col(0).dot(a));
      d.ddq[m.idxV[i]] = qdd;
      d.A[i] = a + s * qdd;
    } else if (nv > 0) {
      auto qdd = d.ddq.segment(m.idxV[i], nv);
      qdd.noalias() = d.Dinv[i] * (d.u[i] - d.U[i].transpose() * a);
      d.A[i] = a + d.S[i] * qdd;
    } else {
      d.A[i] = a;
    }
  }
  return d.ddq;
}

}  // namespace yardsim::dynamics
