#include "dynamics/rnea.hpp"

#include "dynamics/kinematics.hpp"

namespace yardsim::dynamics {

namespace {

// flatten: inline every Eigen helper (GCC otherwise leaves small products and cross products as calls)
template <bool kZeroAcc>
[[gnu::flatten]] void rneaImpl(const Model& m, Data& d, const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Eigen::VectorXd* ddq,
              const ExternalForces* fext, Eigen::VectorXd& out) {
  const bool world = fext != nullptr && fext->hasWorldFrame();
  d.A[0].head<3>().setZero();
  d.A[0].tail<3>() = -m.gravity;
  // (q, v, ddq) => V, A, F = I A + V x* I V - F_ext
  for (int i = 1; i < m.nbodies; ++i) {
    updateJointPlacement(m, d, i, q);
    const int p = m.parent[i];
    if (world) d.X_WB[i] = d.X_WB[p] * d.X_PB[i];
    const int nv = m.jointNv[i];
    const Transform& X = d.X_PB[i];
    if (nv == 1) {
      const auto s = d.S[i].col(0);
      const double vi = v[m.idxV[i]];
      const Motion vJ = s * vi;
      d.V[i] = X.invActMotion(d.V[p]) + vJ;
      Motion a = X.invActMotion(d.A[p]) + crossMotion(d.V[i], vJ);
      if constexpr (!kZeroAcc) a += s * (*ddq)[m.idxV[i]];
      d.A[i] = a;
    } else {
      const auto vi = v.segment(m.idxV[i], nv);
      const Motion vJ = d.S[i] * vi;
      d.V[i] = X.invActMotion(d.V[p]) + vJ;
      Motion a = X.invActMotion(d.A[p]) + crossMotion(d.V[i], vJ) +
                 jointBias(m.joints[i], q.data() + m.idxQ[i], v.data() + m.idxV[i]);
      if constexpr (!kZeroAcc) a += d.S[i] * ddq->segment(m.idxV[i], nv);
      d.A[i] = a;
    }
    const SpatialInertia& I = m.inertias[i];
    d.F[i] = I.apply(d.A[i]) + crossForce(d.V[i], I.apply(d.V[i]));
    if (fext != nullptr) d.F[i] -= fext->inBodyFrame(d, i);
  }
  // (F) => tau = S^T F, F_parent += X^* F
  for (int i = m.nbodies - 1; i >= 1; --i) {
    const int nv = m.jointNv[i];
    if (nv == 1) {
      out[m.idxV[i]] = d.S[i].col(0).dot(d.F[i]);
    } else if (nv > 0) {
      out.segment(m.idxV[i], nv).noalias() = d.S[i].transpose() * d.F[i];
    }
    const int p = m.parent[i];
    if (p > 0) d.F[p] += d.X_PB[i].actForce(d.F[i]);
  }
}

}  // namespace

const Eigen::VectorXd& rnea(const Model& m, Data& d, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                            const Eigen::VectorXd& ddq, const ExternalForces* fext) {
  rneaImpl<false>(m, d, q, v, &ddq, fext, d.tau);
  return d.tau;
}

const Eigen::VectorXd& biasForces(const Model& m, Data& d, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                  const ExternalForces* fext) {
  rneaImpl<true>(m, d, q, v, nullptr, fext, d.nle);
  return d.nle;
}

}  // namespace yardsim::dynamics
