#include "dynamics/crba.hpp"

#include "dynamics/kinematics.hpp"

namespace yardsim::dynamics {

const Eigen::MatrixXd& crba(const Model& m, Data& d, const Eigen::VectorXd& q) {
  // (q) => X_WB, S_W, IC_W = X_WB^* I X_WB^-1
  for (int i = 1; i < m.nbodies; ++i) {
    updateJointPlacement(m, d, i, q);
    d.X_WB[i] = d.X_WB[m.parent[i]] * d.X_PB[i];
    for (int k = 0; k < m.jointNv[i]; ++k) d.S_W.col(m.idxV[i] + k) = d.X_WB[i].actMotion(d.S[i].col(k));
    d.IC_W[i] = actInertia(d.X_WB[i], m.inertiaMatrices[i]);
  }
  // (IC_W) => composite inertias of subtrees
  for (int i = m.nbodies - 1; i >= 1; --i) {
    if (m.parent[i] > 0) d.IC_W[m.parent[i]] += d.IC_W[i];
  }
  // (IC_W, S_W) => M_ji = S_j^T IC_i S_i for j on the path from i to the root
  for (int i = 1; i < m.nbodies; ++i) {
    const int nv = m.jointNv[i];
    const int vi = m.idxV[i];
    for (int k = 0; k < nv; ++k) {
      const Force F = d.IC_W[i] * d.S_W.col(vi + k);
      for (int j = i; j > 0; j = m.parent[j]) {
        for (int l = 0; l < m.jointNv[j]; ++l) {
          const double h = d.S_W.col(m.idxV[j] + l).dot(F);
          d.M(m.idxV[j] + l, vi + k) = h;
          d.M(vi + k, m.idxV[j] + l) = h;
        }
      }
    }
  }
  return d.M;
}

void choleskyFactor(const Model&, Data& d) { d.llt.compute(d.M); }

}  // namespace yardsim::dynamics
