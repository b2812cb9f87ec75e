#include "dynamics/rnea.hpp"

#include <type_traits>

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

// (I_B: mass, centre of mass c and inertia about it, all in the body frame; motions a, v in the
// body frame) => I a + v x* I v, as the Newton-Euler equations about the centre of mass (the form
// of inertiaForceCentroidal, in the frame where c and Ic are constant: no rotation): h = m (u + w x
// c), f = m (a_O + alpha x c) + w x h, n = Ic alpha + w x Ic w + c x f; kDiagonal: Ic is diagonal
template <bool kDiagonal>
inline Force inertiaForceBody(const SpatialInertia& I, const Motion& a, const Motion& v) {
  const Vector3& c = I.com;
  const Vector3 w = v.head<3>(), alpha = a.head<3>();
  const Vector3 h = I.mass * (v.tail<3>() + w.cross(c));
  const Vector3 f = I.mass * (a.tail<3>() + alpha.cross(c)) + w.cross(h);
  Vector3 n;
  if constexpr (kDiagonal) {
    const Vector3 dI = I.inertiaCom.diagonal();
    n = dI.cwiseProduct(alpha) + w.cross(dI.cwiseProduct(w));
  } else {
    n = I.inertiaCom * alpha + w.cross(I.inertiaCom * w);
  }
  Force F;
  F.head<3>() = n + c.cross(f);
  F.tail<3>() = f;
  return F;
}

// (p, x) => r = p x x, entry by entry as Eigen's cross (plain doubles)
inline void crossTo(const double* p, const double* x, double* r) {
  r[0] = p[1] * x[2] - p[2] * x[1];
  r[1] = p[2] * x[0] - p[0] * x[2];
  r[2] = p[0] * x[1] - p[1] * x[0];
}

// (I_B; a, v in the body frame, plain doubles) => F = I a + v x* I v into out, inertiaForceBody's
// operations on plain doubles (loaded and stored one by one, as revoluteForward writes a and v)
template <bool kDiagonal>
inline void inertiaForceBodyTo(const SpatialInertia& I, const double* a, const double* v,
                               double* out) {
  const double c[3] = {I.com[0], I.com[1], I.com[2]};
  const double mass = I.mass;
  double wc[3], ac[3], h[3], f[3], wh[3], n[3], cf[3];
  crossTo(v, c, wc);
  crossTo(a, c, ac);
  for (int k = 0; k < 3; ++k) h[k] = mass * (v[3 + k] + wc[k]);
  crossTo(v, h, wh);
  for (int k = 0; k < 3; ++k) f[k] = mass * (a[3 + k] + ac[k]) + wh[k];
  double Ia[3], Iw[3], wIw[3];
  if constexpr (kDiagonal) {
    for (int k = 0; k < 3; ++k) {
      Ia[k] = I.inertiaCom(k, k) * a[k];
      Iw[k] = I.inertiaCom(k, k) * v[k];
    }
  } else {
    const Vector3 alpha(a[0], a[1], a[2]), w(v[0], v[1], v[2]);
    const Vector3 x = I.inertiaCom * alpha, y = I.inertiaCom * w;
    for (int k = 0; k < 3; ++k) {
      Ia[k] = x[k];
      Iw[k] = y[k];
    }
  }
  crossTo(v, Iw, wIw);
  for (int k = 0; k < 3; ++k) n[k] = Ia[k] + wIw[k];
  crossTo(c, f, cf);
  for (int k = 0; k < 3; ++k) {
    out[k] = n[k] + cf[k];
    out[3 + k] = f[k];
  }
}

// (s, c of an angle about coordinate axis K; x) => R^T x, R the rotation by the angle: the axis
// component kept, the two others mixed (4 products instead of a 3x3's 9)
template <int K>
inline Vector3 rotateBack(double s, double c, const Vector3& x) {
  constexpr int a = (K + 1) % 3, b = (K + 2) % 3;
  Vector3 r;
  r[K] = x[K];
  r[a] = c * x[a] + s * x[b];
  r[b] = c * x[b] - s * x[a];
  return r;
}

// (s, c of an angle about coordinate axis K; x) => R x
template <int K>
inline Vector3 rotate(double s, double c, const Vector3& x) {
  constexpr int a = (K + 1) % 3, b = (K + 2) % 3;
  Vector3 r;
  r[K] = x[K];
  r[a] = c * x[a] - s * x[b];
  r[b] = c * x[b] + s * x[a];
  return r;
}

// (s, c of an angle about coordinate axis K; x) => R^T x in r, as rotateBack (plain doubles)
template <int K>
inline void rotateBackTo(double s, double c, const double* x, double* r) {
  constexpr int a = (K + 1) % 3, b = (K + 2) % 3;
  r[K] = x[K];
  r[a] = c * x[a] + s * x[b];
  r[b] = c * x[b] - s * x[a];
}

// (body i: revolute about axis K of a joint frame translated by p = X_PJ.p; q, qd, qdd; V_B, A_B
// of its parent) => X_PB[i], V_B[i] = X_BP V_P + e_K qd, A_B[i] = X_BP A_P + V_B[i] x e_K qd +
// e_K qdd, where X_BP (w, u) = (R^T w, R^T (u - p x w)); e_K x products are two swapped entries.
// Plain doubles in locals, stored and loaded one by one: Eigen's packet copies of a 6-vector just
// written entry by entry (and packet reads of it in the next body) wait for the stores to drain
// instead of being forwarded, on the chain from body to body (RNEA chain 8: 0.89 of the time in
// the portable build, 0.77 with -march=native)
template <int K>
inline void revoluteForward(const Model& m, Data& d, int i, double q, double qd, double qdd) {
  constexpr int a = (K + 1) % 3, b = (K + 2) % 3;
  double s = 0.0, c = 0.0;
  sinCos(q, s, c);
  Transform& X = d.X_PB[i];
  coordinateAxisRotation(K, s, c, X.R);
  X.p = m.X_PJ[i].p;
  const double p[3] = {X.p[0], X.p[1], X.p[2]};
  const double* vp = d.V_B[m.parent[i]].data();
  const double* ap = d.A_B[m.parent[i]].data();
  double pv[3], pa[3], uv[3], ua[3], vi[6], ai[6];
  crossTo(p, vp, pv);
  crossTo(p, ap, pa);
  for (int k = 0; k < 3; ++k) {
    uv[k] = vp[3 + k] - pv[k];
    ua[k] = ap[3 + k] - pa[k];
  }
  rotateBackTo<K>(s, c, vp, vi);
  rotateBackTo<K>(s, c, uv, vi + 3);
  vi[K] += qd;
  rotateBackTo<K>(s, c, ap, ai);
  rotateBackTo<K>(s, c, ua, ai + 3);
  ai[K] += qdd;
  ai[a] += vi[b] * qd;
  ai[b] -= vi[a] * qd;
  ai[3 + a] += vi[3 + b] * qd;
  ai[3 + b] -= vi[3 + a] * qd;
  double* vo = d.V_B[i].data();
  double* ao = d.A_B[i].data();
  for (int k = 0; k < 6; ++k) {
    vo[k] = vi[k];
    ao[k] = ai[k];
  }
}

// (body i: prismatic along axis K of a translated joint frame) => X_PB[i] (R = 1, p = X_PJ.p +
// e_K q), V_B[i] = X_BP V_P + (0, e_K qd), A_B[i] = X_BP A_P + (0, w x e_K qd) + (0, e_K qdd)
template <int K>
inline void prismaticForward(const Model& m, Data& d, int i, double q, double qd, double qdd) {
  constexpr int a = (K + 1) % 3, b = (K + 2) % 3;
  Transform& X = d.X_PB[i];
  X.R.setIdentity();
  X.p = m.X_PJ[i].p;
  X.p[K] += q;
  const Motion& vp = d.V_B[m.parent[i]];
  const Motion& ap = d.A_B[m.parent[i]];
  Motion vi, ai;
  vi.head<3>() = vp.head<3>();
  vi.tail<3>() = vp.tail<3>() - X.p.cross(vp.head<3>());
  vi[3 + K] += qd;
  ai.head<3>() = ap.head<3>();
  ai.tail<3>() = ap.tail<3>() - X.p.cross(ap.head<3>());
  ai[3 + K] += qdd;
  ai[3 + a] += vi[b] * qd;
  ai[3 + b] -= vi[a] * qd;
  d.V_B[i] = vi;
  d.A_B[i] = ai;
}

// (body i, any joint) => X_PB[i], V_B[i] = X_BP V_P + S v_i, A_B[i] = X_BP A_P + V_B[i] x S v_i +
// c_J + S ddq_i
inline void generalForward(const Model& m, Data& d, int i, const Eigen::VectorXd& q,
                           const Eigen::VectorXd& v, const Eigen::VectorXd& ddq) {
  updateJointPlacement(m, d, i, q);
  const Transform& X = d.X_PB[i];
  const int p = m.parent[i];
  const int nv = m.jointNv[i];
  const int iv = m.idxV[i];
  Motion vJ = Motion::Zero(), aJ = Motion::Zero();
  if (nv > 0) {
    vJ.noalias() = d.S[i] * v.segment(iv, nv);
    aJ.noalias() = d.S[i] * ddq.segment(iv, nv);
  }
  const Motion vi = X.invActMotion(d.V_B[p]) + vJ;
  Motion ai = X.invActMotion(d.A_B[p]) + crossMotion(vi, vJ) + aJ;
  if (!m.joints[i].constantSubspace())
    ai += jointBias(m.joints[i], q.data() + m.idxQ[i], v.data() + iv);
  d.V_B[i] = vi;
  d.A_B[i] = ai;
}

// (k = 0, 1, 2; fn) => fn(std::integral_constant<int, k>): the axis as a compile-time constant
template <class Fn>
inline void withAxis(int k, Fn&& fn) {
  if (k == 0) {
    fn(std::integral_constant<int, 0>{});
  } else if (k == 1) {
    fn(std::integral_constant<int, 1>{});
  } else {
    fn(std::integral_constant<int, 2>{});
  }
}

// (F_B of body i, X_PB[i]: revolute about axis K) => F_B[parent] += X_PB F_B: (R n + p x R f, R f),
// on plain doubles loaded and stored one by one (see revoluteForward)
template <int K>
inline void revoluteToParent(const Transform& X, const Force& F, Force& Fp) {
  constexpr int a = (K + 1) % 3, b = (K + 2) % 3;
  const double s = X.R(b, a);  // sin
  const double c = X.R(a, a);  // cos
  const double p[3] = {X.p[0], X.p[1], X.p[2]};
  const double* fb = F.data();
  double f[3], n[3], pf[3];
  const auto rotateTo = [&](const double* x, double* r) {
    r[K] = x[K];
    r[a] = c * x[a] - s * x[b];
    r[b] = c * x[b] + s * x[a];
  };
  rotateTo(fb + 3, f);
  rotateTo(fb, n);
  crossTo(p, f, pf);
  double* fp = Fp.data();
  for (int k = 0; k < 3; ++k) {
    fp[k] += n[k] + pf[k];
    fp[3 + k] += f[k];
  }
}

// (q, v, ddq, fext) => tau, in the body frame of each body (Featherstone's table 5.1, as RBDL):
// V_B, A_B (including -g), and in F_W the force of each joint on its body about the body origin
// in the body frame; coordinate-axis revolute and prismatic joints of translated frames take the
// steps above, the inertia is applied where it is constant. Without external forces in the
// world frame or added mass no world pose is formed
YARDSIM_FLATTEN void rneaBodyFrame(const Model& m, Data& d, const Eigen::VectorXd& q,
                                   const Eigen::VectorXd& v, const Eigen::VectorXd& ddq,
                                   const ExternalForces* fext, Eigen::VectorXd& out) {
  d.V_B[0].setZero();
  d.A_B[0].head<3>().setZero();
  d.A_B[0].tail<3>() = -m.gravity;
  bool world = fext != nullptr && fext->hasWorldFrame();
  for (int i = 1; i < m.nbodies && !world; ++i) world = d.hasAddedMass[i] != 0;
  // (q, v, ddq) => X_PB, V_B, A_B, F = I A_B + V_B x* I V_B - F_ext (body frame)
  for (int i = 1; i < m.nbodies; ++i) {
    const int k = m.jointAxis[i];
    const int iv = m.idxV[i];
    if (k >= 0 && !m.placementRotated[i]) {
      const double qi = q[m.idxQ[i]], qd = v[iv], qdd = ddq[iv];
      if (m.joints[i].type == JointType::Revolute) {
        withAxis(k, [&](auto K) { revoluteForward<decltype(K)::value>(m, d, i, qi, qd, qdd); });
      } else {
        withAxis(k, [&](auto K) { prismaticForward<decltype(K)::value>(m, d, i, qi, qd, qdd); });
      }
    } else {
      generalForward(m, d, i, q, v, ddq);
    }
    if (!world && fext == nullptr) {
      // (A_B, V_B written one double at a time) => F_W[i], read and written the same way
      const double* ai = d.A_B[i].data();
      const double* vi = d.V_B[i].data();
      double* fw = d.F_W[i].data();
      if (m.inertiaDiagonal[i]) {
        inertiaForceBodyTo<true>(m.inertias[i], ai, vi, fw);
      } else {
        inertiaForceBodyTo<false>(m.inertias[i], ai, vi, fw);
      }
      continue;
    }
    const Motion& vi = d.V_B[i];
    const Motion& ai = d.A_B[i];
    Force F = m.inertiaDiagonal[i] ? inertiaForceBody<true>(m.inertias[i], ai, vi)
                                   : inertiaForceBody<false>(m.inertias[i], ai, vi);
    if (world) {
      d.X_WB[i] = d.X_WB[m.parent[i]] * d.X_PB[i];
      if (d.hasAddedMass[i]) {
        // (A_B, added mass about the body origin) => A a + v x* A v; gravity, folded into the
        // base acceleration -g, acts on the rigid mass only: A (0, R_WB^T g) taken back
        const Matrix6& A = d.addedMass[i];
        F += A * ai + crossForce(vi, A * vi) +
             A.rightCols<3>() * (d.X_WB[i].R.transpose() * m.gravity);
      }
      if (fext != nullptr) F -= d.X_WB[i].invActForce(fext->worldFrame(i));
    }
    if (fext != nullptr) F -= fext->bodyFrame(i);
    d.F_W[i] = F;
  }
  // (F) => tau = S^T F, F(parent) += X_PB F
  for (int i = m.nbodies - 1; i >= 1; --i) {
    const int k = m.jointAxis[i];
    const int iv = m.idxV[i];
    const int nv = m.jointNv[i];
    const int p = m.parent[i];
    const Force& F = d.F_W[i];
    const Transform& X = d.X_PB[i];
    if (k >= 0 && !m.placementRotated[i]) {
      if (m.joints[i].type == JointType::Revolute) {
        out[iv] = F[k];
        if (p == 0) continue;
        withAxis(k, [&](auto K) { revoluteToParent<decltype(K)::value>(X, F, d.F_W[p]); });
      } else {
        out[iv] = F[3 + k];
        if (p == 0) continue;
        d.F_W[p].head<3>() += F.head<3>() + X.p.cross(F.tail<3>());
        d.F_W[p].tail<3>() += F.tail<3>();
      }
      continue;
    }
    if (nv > 0) out.segment(iv, nv).noalias() = d.S[i].transpose() * F;
    if (p > 0) d.F_W[p] += X.actForce(F);
  }
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

const Eigen::VectorXd& rnea(const Model& m, Data& d, const Eigen::VectorXd& q,
                            const Eigen::VectorXd& v, const Eigen::VectorXd& ddq,
                            const ExternalForces* fext) {
  YARDSIM_DYNAMICS_CHECK(m, d, q, &v, &ddq, "rnea");
  rneaBodyFrame(m, d, q, v, ddq, fext, d.tau);
  return d.tau;
}

const Eigen::VectorXd& rneaWorld(const Model& m, Data& d, const Eigen::VectorXd& q,
                                 const Eigen::VectorXd& v, const Eigen::VectorXd& ddq,
                                 const ExternalForces* fext) {
  YARDSIM_DYNAMICS_CHECK(m, d, q, &v, &ddq, "rneaWorld");
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
  // (joints of forward) => whether none of them rotates
  translational = any;
  for (int i = 1; i < m.nbodies && translational; ++i) {
    const JointType t = m.joints[i].type;
    translational = forward[static_cast<std::size_t>(i)] == 0 || t == JointType::Prismatic ||
                    t == JointType::Translation || t == JointType::Fixed;
  }
}

namespace {

// (translational mask, placements) => data.nle of the subtree's joints: with no rotation from the
// world down, every body's acceleration at zero ddq is the base's -g and its velocity products
// vanish, so a joint carries the weight of its subtree, S^T sum m (-g) (linear parts only). False,
// untouched, when a body of the subtree has added mass (its share of -g differs).
bool translationalBias(const Model& m, Data& d, const Data& k, const SubtreeMask& sub) {
  for (int i = 1; i < m.nbodies; ++i)
    if (sub.subtree[static_cast<std::size_t>(i)] && d.hasAddedMass[i]) return false;
  // (mass) => its weight's reaction m (-g), the subtree's summed leaves first (children follow
  // their parents in the body order)
  for (int i = 1; i < m.nbodies; ++i)
    if (sub.subtree[static_cast<std::size_t>(i)])
      d.F_W[i].tail<3>() = m.inertias[i].mass * (-m.gravity);
  for (int i = m.nbodies - 1; i >= 1; --i) {
    if (!sub.subtree[static_cast<std::size_t>(i)]) continue;
    const Vector3& f = d.F_W[i].tail<3>();
    const int nv = m.jointNv[i];
    const int iv = m.idxV[i];
    if (nv == 1) {
      d.nle[iv] = worldSubspaceColumn(m, k, i).tail<3>().dot(f);
    } else {
      for (int c = 0; c < nv; ++c) d.nle[iv + c] = (k.X_WB[i].R * k.S[i].col(c).tail<3>()).dot(f);
    }
    const int p = m.parent[i];
    if (p > 0 && sub.subtree[static_cast<std::size_t>(p)]) d.F_W[p].tail<3>() += f;
  }
  return true;
}

}  // namespace

const Eigen::VectorXd& biasForcesOfSubtrees(const Model& m, Data& d, const Data& placed,
                                            const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                            const SubtreeMask& sub) {
  YARDSIM_DYNAMICS_CHECK(m, d, q, &v, nullptr, "biasForcesOfSubtrees");
  if (sub.translational && translationalBias(m, d, placed, sub)) return d.nle;
  rneaImpl<true>(m, d, q, v, nullptr, nullptr, d.nle, &placed, &sub);
  return d.nle;
}

}  // namespace yardsim::dynamics
