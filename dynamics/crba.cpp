#include "dynamics/crba.hpp"

#include "dynamics/checks.hpp"
#include "dynamics/flatten.hpp"
#include "dynamics/kinematics.hpp"

namespace yardsim::dynamics {

// flatten (YARDSIM_FLATTEN): inline every Eigen helper (GCC otherwise leaves small products as
// calls)
YARDSIM_FLATTEN const Eigen::MatrixXd& crba(const Model& m, Data& d, const Eigen::VectorXd& q) {
  YARDSIM_DYNAMICS_CHECK(m, d, q, nullptr, nullptr, "crba");
  // (q) => X_WB, S_W, IC_W = X_WB^* (I + A) X_WB^-1 (A: added mass)
  // (placeBody, worldSubspaceColumn, matrixIn<true>: the shortcuts of RNEA and ABA for
  // coordinate-axis joints and diagonal inertias, equal in value to the general products)
  for (int i = 1; i < m.nbodies; ++i) {
    placeBody(m, d, i, q);
    if (m.jointNv[i] == 1) {
      d.S_W.col(m.idxV[i]) = worldSubspaceColumn(m, d, i);
    } else {
      for (int k = 0; k < m.jointNv[i]; ++k) d.S_W.col(m.idxV[i] + k) = d.X_WB[i].actMotion(d.S[i].col(k));
    }
    d.IC_W[i] = m.inertiaDiagonal[i] ? m.inertias[i].matrixIn<true>(d.X_WB[i]) : m.inertias[i].matrixIn(d.X_WB[i]);
    if (d.hasAddedMass[i]) d.IC_W[i] += actInertia(d.X_WB[i], d.addedMass[i]);
  }
  // (IC_W) => composite inertias of subtrees
  for (int i = m.nbodies - 1; i >= 1; --i) {
    if (m.parent[i] > 0) d.IC_W[m.parent[i]] += d.IC_W[i];
  }
  // (IC_W, S_W) => F = IC_W S_W per dof; column block of body i over its subtree: M = F^T S_i
  for (int i = m.nbodies - 1; i >= 1; --i) {
    const int nv = m.jointNv[i];
    if (nv == 0) continue;
    const int iv = m.idxV[i];
    const int ns = m.nvSubtree[i];
    d.Fcrb.middleCols(iv, nv).noalias() = d.IC_W[i] * d.S_W.middleCols(iv, nv);
    for (int k = 0; k < nv; ++k) {
      d.M.col(iv + k).segment(iv, ns).noalias() = d.Fcrb.middleCols(iv, ns).transpose() * d.S_W.col(iv + k);
    }
  }
  // (lower triangle) => upper triangle; entries between bodies on different branches stay zero
  for (int c = 1; c < m.nv; ++c) {
    for (int r = 0; r < c; ++r) d.M(r, c) = d.M(c, r);
  }
  return d.M;
}

}  // namespace yardsim::dynamics
