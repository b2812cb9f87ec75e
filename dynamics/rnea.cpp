#include "dynamics/rnea.hpp"

#include "dynamics/checks.hpp"
#include "dynamics/flatten.hpp"
#include "dynamics/kinematics.hpp"

namespace yardsim::dynamics {

namespace {

// (I_B: mass, centre of mass and inertia about it in the body frame; X_WB; motions a, v in the
// world frame) => I_W a + v x* (I_W v) without forming the 6x6 I_W, as the Newton-Euler equations
// about the centre of mass c (in the world): with v_c = v_O + w x c, the velocity of the point c,
// f = m (a_O + alpha x c) + w x (m v_c) and n = R (Ic alpha_B + w_B x Ic w_B) + c x f, where
// alpha_B = R^T alpha, w_B = R^T w (the gyroscopic moment in the body frame, where Ic is
// constant); kDiagonal: Ic is diagonal, Ic x scales x (the same values)
template <bool kDiagonal>
inline Force inertiaForceCentroidal(const SpatialInertia& I, const Transform& X, const Motion& a,
                                    const Motion& v) {
  const Vector3 c = X.R * I.com + X.p;
  const Vector3 w = v.head<3>(), alpha = a.head<3>();
  const Vector3 hv = I.mass * (v.tail<3>() + w.cross(c));
  const Vector3 f = I.mass * (a.tail<3>() + alpha.cross(c)) + w.cross(hv);
  const Vector3 alphaB = X.R.transpose() * alpha;
  const Vector3 wB = X.R.transpose() * w;
  Vector3 nB;
  if constexpr (kDiagonal) {
    const Vector3 d = I.inertiaCom.diagonal();
    nB = d.cwiseProduct(alphaB) + wB.cross(d.cwiseProduct(wB));
  } else {
    nB = I.inertiaCom * alphaB + wB.cross(I.inertiaCom * wB);
  }
  Force F;
  F.head<3>() = X.R * nB + c.cross(f);
  F.tail<3>() = f;
  return F;
}

// (I_B, X_WB; motions a, v in the world frame) => I_W a + v x* (I_W v), the spatial form (the
// doubles biasForces has always returned, which the integrated trajectories of the scenes are made
// of: a last-bit change there grows to 1e-7 of a channel's range in the megablock example): for a
// motion (w, u),
// h = m (u + w x c) and n = R Ic R^T w + c x h, c being the centre of mass in the world;
// kDiagonal: Ic is diagonal, Ic x scales x (the same values)
template <bool kDiagonal>
inline Force inertiaForceSpatial(const SpatialInertia& I, const Transform& X, const Motion& a,
                                 const Motion& v) {
  const Vector3 c = X.R * I.com + X.p;
  const Vector3 wa = a.head<3>(), wv = v.head<3>();
  const Vector3 ha = I.mass * (a.tail<3>() + wa.cross(c));
  const Vector3 hv = I.mass * (v.tail<3>() + wv.cross(c));
  Force Ia, Iv;
  Vector3 Ja, Jv;  // Ic R^T w
  if constexpr (kDiagonal) {
    Ja = I.inertiaCom.diagonal().cwiseProduct(X.R.transpose() * wa);
    Jv = I.inertiaCom.diagonal().cwiseProduct(X.R.transpose() * wv);
  } else {
    Ja = I.inertiaCom * (X.R.transpose() * wa);
    Jv = I.inertiaCom * (X.R.transpose() * wv);
  }
  Ia.head<3>() = X.R * Ja + c.cross(ha);
  Ia.tail<3>() = ha;
  Iv.head<3>() = X.R * Jv + c.cross(hv);
  Iv.tail<3>() = hv;
  return Ia + crossForce(v, Iv);
}

// flatten (YARDSIM_FLATTEN): inline every Eigen helper (GCC otherwise leaves small products and
// cross products as calls); kZeroAcc: ddq = 0 (biasForces), which also keeps the spatial form of
// the inertia force (inertiaForceSpatial); rnea takes the centroidal form (inertiaForceCentroidal).
// placed: null, or a Data whose X_WB and S already hold q's placements (used instead of placing
// the bodies again: the same doubles); sub: null, or the bodies whose joint forces are wanted (a
// set closed under children: only they get an inertia force and a backward step, and only they
// and their ancestors a forward step; the other entries of out are left as they were)
template <bool kZeroAcc>
YARDSIM_FLATTEN void rneaImpl(const Model& m, Data& d, const Eigen::VectorXd& q,
                              const Eigen::VectorXd& v, const Eigen::VectorXd* ddq,
                              const ExternalForces* fext, Eigen::VectorXd& out,
                              const Data* placed = nullptr, const SubtreeMask* sub = nullptr) {
  const Data& k = placed != nullptr ? *placed : d;
  d.A_W[0].head<3>().setZero();
  d.A_W[0].tail<3>() = -m.gravity;
  // (q, v, ddq) => X_WB, S_W, V_W, A_W, F_W = I_W A_W + V_W x* I_W V_W - F_ext_W
  for (int i = 1; i < m.nbodies; ++i) {
    if (sub != nullptr && !sub->forward[static_cast<std::size_t>(i)]) continue;
    if (placed == nullptr) placeBody(m, d, i, q);
    const int p = m.parent[i];
    const Transform& X = k.X_WB[i];
    const int nv = m.jointNv[i];
    const int iv = m.idxV[i];
    if (nv == 1) {
      const Motion s = worldSubspaceColumn(m, k, i);
      d.S_W.col(iv) = s;
      const Motion vJ = s * v[iv];
      d.V_W[i] = d.V_W[p] + vJ;
      d.A_W[i] = d.A_W[p] + crossMotion(d.V_W[i], vJ);
      if constexpr (!kZeroAcc) d.A_W[i] += s * (*ddq)[iv];
    } else {
      for (int c = 0; c < nv; ++c) d.S_W.col(iv + c) = X.actMotion(k.S[i].col(c));
      const auto S = d.S_W.middleCols(iv, nv);
      const Motion vJ = nv > 0 ? Motion(S * v.segment(iv, nv)) : Motion::Zero();
      d.V_W[i] = d.V_W[p] + vJ;
      d.A_W[i] = d.A_W[p] + crossMotion(d.V_W[i], vJ);
      if (!m.joints[i].constantSubspace()) {
        d.A_W[i] += X.actMotion(jointBias(m.joints[i], q.data() + m.idxQ[i], v.data() + iv));
      }
      if constexpr (!kZeroAcc) {
        if (nv > 0) d.A_W[i] += S * ddq->segment(iv, nv);
      }
    }
    if (sub != nullptr && !sub->subtree[static_cast<std::size_t>(i)]) continue;
    if (d.hasAddedMass[i]) {
      // I + A_W (added mass); gravity, folded into the base acceleration -g, acts on the rigid
      // mass only: A_W (0, -g) is taken back
      const Matrix6 A_W = actInertia(X, d.addedMass[i]);
      const Matrix6 I = m.inertias[i].matrixIn(X) + A_W;
      d.F_W[i] = I * d.A_W[i] + crossForce(d.V_W[i], I * d.V_W[i]) + A_W.rightCols<3>() * m.gravity;
    } else {
      const SpatialInertia& I = m.inertias[i];
      if constexpr (kZeroAcc) {
        d.F_W[i] = m.inertiaDiagonal[i] ? inertiaForceSpatial<true>(I, X, d.A_W[i], d.V_W[i])
                                        : inertiaForceSpatial<false>(I, X, d.A_W[i], d.V_W[i]);
      } else {
        d.F_W[i] = m.inertiaDiagonal[i] ? inertiaForceCentroidal<true>(I, X, d.A_W[i], d.V_W[i])
                                        : inertiaForceCentroidal<false>(I, X, d.A_W[i], d.V_W[i]);
      }
    }
    if (fext != nullptr) d.F_W[i] -= X.actForce(fext->bodyFrame(i)) + fext->worldFrame(i);
  }
  // (F_W) => tau = S_W^T F_W, F_W(parent) += F_W
  for (int i = m.nbodies - 1; i >= 1; --i) {
    if (sub != nullptr && !sub->subtree[static_cast<std::size_t>(i)]) continue;
    const int nv = m.jointNv[i];
    const int iv = m.idxV[i];
    if (nv == 1) {
      out[iv] = d.S_W.col(iv).dot(d.F_W[i]);
    } else if (nv > 0) {
      out.segment(iv, nv).noalias() = d.S_W.middleCols(iv, nv).transpose() * d.F_W[i];
    }
    const int p = m.parent[i];
    if (p > 0 && (sub == nullptr || sub->subtree[static_cast<std::size_t>(p)]))
      d.F_W[p] += d.F_W[i];
  }
}

}  // namespace

const Eigen::VectorXd& rnea(const Model& m, Data& d, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                            const Eigen::VectorXd& ddq, const ExternalForces* fext) {
  YARDSIM_DYNAMICS_CHECK(m, d, q, &v, &ddq, "rnea");
  rneaImpl<false>(m, d, q, v, &ddq, fext, d.tau);
  return d.tau;
}

const Eigen::VectorXd& biasForces(const Model& m, Data& d, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                  const ExternalForces* fext) {
  rneaImpl<true>(m, d, q, v, nullptr, fext, d.nle);
  return d.nle;
}

void SubtreeMask::mark(const Model& m, const std::vector<char>& roots) {
  // (roots) => subtree: a body is in it when it or its parent is; forward: the subtree and every
  // ancestor of it
  subtree.assign(static_cast<std::size_t>(m.nbodies), 0);
  forward.assign(static_cast<std::size_t>(m.nbodies), 0);
  any = false;
  for (int i = 1; i < m.nbodies; ++i) {
    const auto u = static_cast<std::size_t>(i);
    subtree[u] = (roots[u] != 0 || subtree[static_cast<std::size_t>(m.parent[i])] != 0) ? 1 : 0;
    forward[u] = subtree[u];
    any = any || subtree[u] != 0;
  }
  for (int i = m.nbodies - 1; i >= 1; --i)
    if (forward[static_cast<std::size_t>(i)] != 0)
      forward[static_cast<std::size_t>(m.parent[i])] = 1;
}

const Eigen::VectorXd& biasForcesOfSubtrees(const Model& m, Data& d, const Data& placed,
                                            const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                            const SubtreeMask& sub) {
  YARDSIM_DYNAMICS_CHECK(m, d, q, &v, nullptr, "biasForcesOfSubtrees");
  rneaImpl<true>(m, d, q, v, nullptr, nullptr, d.nle, &placed, &sub);
  return d.nle;
}

}  // namespace yardsim::dynamics
