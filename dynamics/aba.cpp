#include "dynamics/aba.hpp"

#include <Eigen/LU>

#include "dynamics/checks.hpp"
#include "dynamics/flatten.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/subspace_column.hpp"

namespace yardsim::dynamics {

namespace {

// The passes carry the bias accelerations from the root instead of each joint's own: pass 1
// leaves in A_W[i] the acceleration body i would have with ddq = 0, A0_i = A0_parent + C_W[i]
// (A0 of the world -g), and the bias force PA_W[i] = I_i A0_i + V_i x* I_i V_i - F_ext_i. With
// a_i = A0_i + da_i, da_i = da_parent + S qdd, ABA's recursions for da have no velocity-product
// terms: the parent receives Ia (as before) and pa = PA + U D^-1 u, u = tau - S^T PA, and
// qdd = D^-1 (u - U^T da_parent) = D^-1 (u + U^T A0_parent - U^T a_parent). Equal to the textbook
// form (Featherstone, table 7.1) to round-off: IA_i A0_i sums I_i A0_i (10 numbers, not a 6x6
// product) over the subtree, and the textbook's IA c of every body is not formed.

// (body inertia, X_WB, V = (w, v) and A0 = (al, a) of the body, world frame) => I, its 6x6 inertia
// about the world origin in world axes (the values of SpatialInertia::matrixIn), and
// I A0 + V x* I V from its centre of mass c and rotational inertia J = R Ic R^T there (the
// Newton-Euler form): f = m (a + al x c + w x (v + w x c)), n = c x f + J al + w x J w
inline Force rigidBodyTerms(const SpatialInertia& I, bool diagonal, const Transform& X,
                            const Motion& V, const Motion& A0, Matrix6& M) {
  const Matrix3& R = X.R;
  using Vector2 = Eigen::Vector2d;
  const Vector3& b = I.com;
  // (R, b, p) => c = R b + p: rows 0-1 as one pair (SSE2's width), row 2 alone
  const Vector2 c01 = (R.col(0).head<2>() * b[0] + R.col(1).head<2>() * b[1]) +
                      (R.col(2).head<2>() * b[2] + X.p.head<2>());
  const Vector3 c(c01[0], c01[1], (R(2, 0) * b[0] + R(2, 1) * b[1]) + (R(2, 2) * b[2] + X.p[2]));
  Matrix3 G;  // R Ic
  if (diagonal) {
    G = R * I.inertiaCom.diagonal().asDiagonal();
  } else {
    G = R * I.inertiaCom;
  }
  // (G, R) => J = G R^T's lower triangle: (j00, j10) = sum_k G(0:1, k) R(0, k), (j20, j21) =
  // sum_k G(2, k) R(0:1, k), j11 and j22 alone
  const Vector2 j0 =
      (G.col(0).head<2>() * R(0, 0) + G.col(1).head<2>() * R(0, 1)) + G.col(2).head<2>() * R(0, 2);
  const Vector2 j2 =
      (R.col(0).head<2>() * G(2, 0) + R.col(1).head<2>() * G(2, 1)) + R.col(2).head<2>() * G(2, 2);
  const double j00 = j0[0], j10 = j0[1], j20 = j2[0], j21 = j2[1];
  const double j11 = (G(1, 0) * R(1, 0) + G(1, 1) * R(1, 1)) + G(1, 2) * R(1, 2);
  const double j22 = (G(2, 0) * R(2, 0) + G(2, 1) * R(2, 1)) + G(2, 2) * R(2, 2);
  const double m = I.mass;
  const Vector3 h = m * c;
  // (J, m, c) => [[O, [h]x], [-[h]x, m 1]], O = J + m (|c|^2 1 - c c^T), column by column
  const double o00 = j00 + (h[1] * c[1] + h[2] * c[2]), o10 = j10 - h[1] * c[0],
               o20 = j20 - h[2] * c[0];
  const double o11 = j11 + (h[0] * c[0] + h[2] * c[2]), o21 = j21 - h[2] * c[1];
  const double o22 = j22 + (h[0] * c[0] + h[1] * c[1]);
  // (the lower block triangle only, kLowerBlocks: the 1-dof joints read nothing else)
  M.col(0) << o00, o10, o20, 0.0, -h[2], h[1];
  M.col(1) << o10, o11, o21, h[2], 0.0, -h[0];
  M.col(2).tail<4>() << o22, -h[1], h[0], 0.0;
  M.col(3).tail<4>() << -h[1], m, 0.0, 0.0;
  M.col(4).tail<2>() << m, 0.0;
  M.col(5).tail<2>() << 0.0, m;
  // (V, A0, c, J) => the Newton-Euler force and moment about the origin
  const Vector3 w = V.head<3>(), al = A0.head<3>();
  const auto J = [&](const Vector3& x) {
    return Vector3(j00 * x[0] + j10 * x[1] + j20 * x[2], j10 * x[0] + j11 * x[1] + j21 * x[2],
                   j20 * x[0] + j21 * x[1] + j22 * x[2]);
  };
  const Vector3 vc = V.tail<3>() + w.cross(c);
  Force f;
  f.tail<3>() = m * (A0.tail<3>() + al.cross(c) + w.cross(vc));
  f.head<3>() = c.cross(f.tail<3>()) + J(al) + w.cross(J(w));
  return f;
}

// The articulated inertias IA_W are symmetric; the 1-dof joints read and write only their lower
// block triangle, the 2x2 blocks (rows 2r, 2r + 1; columns 2c, 2c + 1) with r >= c: 12 pairs of
// doubles, each one SSE2 register (kLowerBlocks, as (row, column) of the pair's first entry).
// The upper block triangle is left stale; the joints that read all of IA (multi-dof, the free
// root) fill it from the lower first (symmetrizeFromLower).
using Pair = Eigen::Vector2d;
constexpr int kLowerBlocks[12][2] = {{0, 0}, {2, 0}, {4, 0}, {0, 1}, {2, 1}, {4, 1},
                                     {2, 2}, {4, 2}, {2, 3}, {4, 3}, {4, 4}, {4, 5}};

// (A, pair at row r of column c) => a view of A(r : r + 1, c), 16-byte aligned (r even)
inline Eigen::Map<Pair, Eigen::Aligned16> pairAt(Matrix6& A, int r, int c) {
  return Eigen::Map<Pair, Eigen::Aligned16>(A.data() + 6 * c + r);
}
inline Eigen::Map<const Pair, Eigen::Aligned16> pairAt(const Matrix6& A, int r, int c) {
  return Eigen::Map<const Pair, Eigen::Aligned16>(A.data() + 6 * c + r);
}

// (x, y) => (x0 + x1, y0 + y1): the products of a transposed block by a pair, summed
inline Pair pairSums(const Pair& x, const Pair& y) {
  return Pair(x[0], y[0]) + Pair(x[1], y[1]);
}

// (IA's lower block triangle, s) => IA s, the upper blocks' products taken as the transposed
// lower ones': U(0:1) = B00 s01 + B10^T s23 + B20^T s45, U(2:3) = B10 s01 + B11 s23 + B21^T s45,
// U(4:5) = B20 s01 + B21 s23 + B22 s45
inline Vector6 lowerTimes(const Matrix6& A, const Motion& s) {
  const Pair s23 = s.segment<2>(2), s45 = s.segment<2>(4);
  const auto P = [&](int r, int c) { return pairAt(A, r, c); };
  const Pair a = (P(0, 0) * s[0] + P(0, 1) * s[1]) +
                 pairSums(P(2, 0).cwiseProduct(s23) + P(4, 0).cwiseProduct(s45),
                          P(2, 1).cwiseProduct(s23) + P(4, 1).cwiseProduct(s45));
  const Pair b = (P(2, 0) * s[0] + P(2, 1) * s[1]) + (P(2, 2) * s[2] + P(2, 3) * s[3]) +
                 pairSums(P(4, 2).cwiseProduct(s45), P(4, 3).cwiseProduct(s45));
  const Pair c = (P(4, 0) * s[0] + P(4, 1) * s[1]) + (P(4, 2) * s[2] + P(4, 3) * s[3]) +
                 (P(4, 4) * s[4] + P(4, 5) * s[5]);
  Vector6 U;
  U << a, b, c;
  return U;
}

// (IA's lower triangle) => its upper triangle, a copy
inline void symmetrizeFromLower(Matrix6& A) {
  for (int c = 1; c < 6; ++c)
    for (int r = 0; r < c; ++r) A(r, c) = A(c, r);
}

// (symmetric positive definite D, 6 x 6) => its L D L^T factors in place: L's strict lower
// triangle (unit diagonal implied) and D's pivots on the diagonal; the upper triangle is not read
inline void ldltInPlace6(Eigen::Map<Matrix6> A) {
  for (int j = 0; j < 6; ++j) {
    double dj = A(j, j);
    for (int k = 0; k < j; ++k) dj -= A(j, k) * A(j, k) * A(k, k);
    A(j, j) = dj;
    const double inv = 1.0 / dj;
    for (int i = j + 1; i < 6; ++i) {
      double aij = A(i, j);
      for (int k = 0; k < j; ++k) aij -= A(i, k) * A(j, k) * A(k, k);
      A(i, j) = aij * inv;
    }
  }
}

// (ldltInPlace6's factors of D, b) => D^-1 b: forward, diagonal and backward substitution
inline Vector6 ldltSolve6(const Eigen::Map<const Matrix6> F, Vector6 b) {
  for (int i = 1; i < 6; ++i)
    for (int k = 0; k < i; ++k) b[i] -= F(i, k) * b[k];
  for (int i = 0; i < 6; ++i) b[i] /= F(i, i);
  for (int i = 4; i >= 0; --i)
    for (int k = i + 1; k < 6; ++k) b[i] -= F(k, i) * b[k];
  return b;
}

// (free joint at the root: IA_W[i], PA_W[i]) => U = IA S, D = S^T U factored as L D L^T in
// Dinv's buffer (the root hands nothing to a parent, so only D^-1 u is needed: one solve
// instead of the inverse, a twelfth of its cost), u = tau - S^T PA
inline void abaFreeRootBackward(Data& d, int i, int iv, const Eigen::VectorXd& tau) {
  symmetrizeFromLower(d.IA_W[i]);
  const Eigen::Map<const Matrix6> S(d.S_W.col(iv).data());
  Eigen::Map<Matrix6> U(d.U[i].data());
  Eigen::Map<Matrix6> F(d.Dinv[i].data());
  U.noalias() = d.IA_W[i] * S;
  F.noalias() = S.transpose() * U;
  ldltInPlace6(F);
  Eigen::Map<Vector6>(d.u[i].data()).noalias() = tau.segment<6>(iv) - S.transpose() * d.PA_W[i];
}

// (free joint at the root, its factors) => ddq = D^-1 u (da_parent = 0), A_W[i] = A_W[0] +
// C_W[i] + S ddq
inline void abaFreeRootForward(Data& d, int i, int iv) {
  const Eigen::Map<const Matrix6> S(d.S_W.col(iv).data());
  auto qdd = d.ddq.segment<6>(iv);
  qdd = ldltSolve6(Eigen::Map<const Matrix6>(d.Dinv[i].data()),
                   Eigen::Map<const Vector6>(d.u[i].data()));
  d.A_W[i] = d.A_W[0] + d.C_W[i] + S * qdd;
}

// (body i with an NV-dof joint, IA_W[i], PA_W[i], A_W[p] = A0_p) => U = IA S, D^-1 = (S^T U)^-1,
// u = tau - S^T PA (stored plus U^T A0_p when p > 0), and Ia = IA - U D^-1 U^T and
// pa = PA + U D^-1 u added to the parent p's; fixed-size maps of Data's buffers, without the
// heap temporaries of the dynamic-size code below (Eigen's dynamic-size inverse takes its LU's
// workspace from malloc at every call)
template <int NV>
inline void abaJointBackward(Data& d, int i, int p, int iv, const Eigen::VectorXd& tau) {
  const Eigen::Map<const Eigen::Matrix<double, 6, NV>> S(d.S_W.col(iv).data());
  Eigen::Map<Eigen::Matrix<double, 6, NV>> U(d.U[i].data());
  Eigen::Map<Eigen::Matrix<double, NV, NV>> Dinv(d.Dinv[i].data());
  Eigen::Map<Eigen::Matrix<double, NV, 1>> u(d.u[i].data());
  symmetrizeFromLower(d.IA_W[i]);
  U.noalias() = d.IA_W[i] * S;
  // (as Eigen's dynamic-size inverse does; its fixed-size one would use closed forms for NV <= 4)
  Dinv = Eigen::PartialPivLU<Eigen::Matrix<double, NV, NV>>(S.transpose() * U).inverse();
  u.noalias() = tau.segment<NV>(iv) - S.transpose() * d.PA_W[i];
  if (p == 0) return;
  const Eigen::Matrix<double, NV, 1> w = Dinv * u;
  u.noalias() += U.transpose() * d.A_W[p];
  d.PA_W[p] += d.PA_W[i] + U * w;
  d.IA_W[p] += d.IA_W[i];
  d.IA_W[p].noalias() -= U * Dinv * U.transpose();
}

// (body i with a 1-dof joint, IA_W[i]'s lower block triangle, PA_W[i], A_W[p] = A0_p, tau_i) =>
// U = IA s, D^-1 = 1 / s^T U, u = tau_i - s^T PA (stored plus U . A0_p when p > 0), and
// pa = PA + U D^-1 u, Ia = IA - U D^-1 U^T added to the parent p's, on its lower block triangle
// (12 pairs of the 18 of a full update)
inline void abaOneDofBackward(Data& d, int i, int p, int iv, double tau) {
  const Motion s = d.S_W.col(iv);
  const Matrix6& IA = d.IA_W[i];
  const Vector6 U = lowerTimes(IA, s);
  const double Dinv = 1.0 / s.dot(U);
  const double ui = tau - s.dot(d.PA_W[i]);
  d.U[i].col(0) = U;
  d.Dinv[i](0, 0) = Dinv;
  if (p == 0) {
    d.u[i][0] = ui;
    return;
  }
  d.u[i][0] = ui + U.dot(d.A_W[p]);
  d.PA_W[p] += d.PA_W[i] + U * (Dinv * ui);
  const Vector6 DU = Dinv * U;
  Matrix6& IAp = d.IA_W[p];
  for (const auto& rc : kLowerBlocks) {
    const int r = rc[0], c = rc[1];
    pairAt(IAp, r, c) = (pairAt(IAp, r, c) + pairAt(IA, r, c)) - DU.segment<2>(r) * U[c];
  }
}

// (body i with an NV-dof joint, a = A_W[p]) => ddq of the joint, A_W[i] = a + C_W[i] + S ddq
// (p = 0: da_parent = 0, ddq = D^-1 u)
template <int NV>
inline void abaJointForward(Data& d, int i, int p, int iv) {
  const Eigen::Map<const Eigen::Matrix<double, 6, NV>> S(d.S_W.col(iv).data());
  const Eigen::Map<const Eigen::Matrix<double, 6, NV>> U(d.U[i].data());
  const Eigen::Map<const Eigen::Matrix<double, NV, NV>> Dinv(d.Dinv[i].data());
  const Eigen::Map<const Eigen::Matrix<double, NV, 1>> u(d.u[i].data());
  const Motion& a = d.A_W[p];
  auto qdd = d.ddq.segment<NV>(iv);
  if (p == 0) {
    qdd.noalias() = Dinv * u;
  } else {
    qdd.noalias() = Dinv * (u - U.transpose() * a);
  }
  d.A_W[i] = a + d.C_W[i] + S * qdd;
}

// (body i on a 1-dof coordinate-axis joint, X_WB[i], qd) => S_W's column (worldSubspaceColumn's
// doubles: (R_WB's column K, p x it) for a revolute, (0, it) for a prismatic joint) and vJ = s qd,
// both written as three pairs formed in registers: the 6-vector worldSubspaceColumn builds entry by
// entry and then copies as pairs waits for its stores instead of having them forwarded
inline void subspaceAndVelocity(const Model& m, Data& d, int i, double qd, Motion& vJ) {
  const Transform& X = d.X_WB[i];
  double s[6];
  coordinateAxisSubspace(m.joints[i].type == JointType::Revolute, X.R.data() + 3 * m.jointAxis[i],
                         X.p.data(), s);
  double* col = d.S_W.col(m.idxV[i]).data();
  for (int r = 0; r < 6; r += 2) {
    const Pair pr(s[r], s[r + 1]);
    Eigen::Map<Pair>(col + r) = pr;
    vJ.segment<2>(r) = pr * qd;
  }
}

// (q, v, body i's X_WB) => S_W, V_W, C_W = V_W x S_W v_i (+ X c_J), A_W = A0_i, IA_W = I_W,
// PA_W = I_W A0_i + V_W x* I_W V_W - F_ext_W
inline void abaBodyTerms(const Model& m, Data& d, int i, const Eigen::VectorXd& q,
                         const Eigen::VectorXd& v, const ExternalForces* fext) {
  const int p = m.parent[i];
  const Transform& X = d.X_WB[i];
  const int nv = m.jointNv[i];
  const int iv = m.idxV[i];
  Motion vJ;
  if (nv == 1 && m.jointAxis[i] >= 0) {
    subspaceAndVelocity(m, d, i, v[iv], vJ);
  } else if (nv == 1) {
    const Motion s = worldSubspaceColumn(m, d, i);
    d.S_W.col(iv) = s;
    vJ = s * v[iv];
  } else {
    for (int k = 0; k < nv; ++k) d.S_W.col(iv + k) = X.actMotion(d.S[i].col(k));
    vJ = d.S_W.middleCols(iv, nv) * v.segment(iv, nv);
    d.C_W[i] = m.joints[i].constantSubspace()
                   ? Motion::Zero()
                   : X.actMotion(jointBias(m.joints[i], q.data() + m.idxQ[i], v.data() + iv));
  }
  const Motion& V = d.V_W[i] = d.V_W[p] + vJ;
  if (nv == 1) {
    d.C_W[i] = crossMotion(V, vJ);  // the 1-dof joints' S is constant: no c_J
  } else {
    d.C_W[i] += crossMotion(V, vJ);
  }
  const Motion& A0 = d.A_W[i] = d.A_W[p] + d.C_W[i];
  const Force f = rigidBodyTerms(m.inertias[i], m.inertiaDiagonal[i] != 0, X, V, A0, d.IA_W[i]);
  if (d.hasAddedMass[i]) {
    // (A_B) => A_W on the left-hand side; gravity, folded into the base acceleration -g, must
    // not act on it: its share A_W (0, -g) goes back as an external force
    const Matrix6 A_W = actInertia(X, d.addedMass[i]);
    d.IA_W[i] += A_W;
    d.PA_W[i] = f + A_W * A0 + crossForce(V, A_W * V) + A_W.rightCols<3>() * m.gravity;
  } else {
    d.PA_W[i] = f;
  }
  if (fext != nullptr) d.PA_W[i] -= X.actForce(fext->bodyFrame(i)) + fext->worldFrame(i);
}

// (q, v, tau, fext; with kPlaced, d.X_PB and d.X_WB already hold q's placements) => ddq
// flatten (YARDSIM_FLATTEN): inline every Eigen helper into the three passes (GCC otherwise leaves
// 6x6 products as calls)
template <bool kPlaced>
YARDSIM_FLATTEN const Eigen::VectorXd& abaPasses(const Model& m, Data& d, const Eigen::VectorXd& q,
                                                 const Eigen::VectorXd& v,
                                                 const Eigen::VectorXd& tau,
                                                 const ExternalForces* fext) {
  // (q, v) => X_WB and the body terms of abaBodyTerms, root to leaves
  d.A_W[0].head<3>().setZero();
  d.A_W[0].tail<3>() = -m.gravity;
  for (int i = 1; i < m.nbodies; ++i) {
    if constexpr (!kPlaced) {
      placeBody(m, d, i, q);
    }
    abaBodyTerms(m, d, i, q, v, fext);
  }
  // (IA, PA) => U = IA S, D^-1, u; articulated inertia and bias added to the parent
  for (int i = m.nbodies - 1; i >= 1; --i) {
    const int nv = m.jointNv[i];
    const int p = m.parent[i];
    const int iv = m.idxV[i];
    if (nv == 1) {
      abaOneDofBackward(d, i, p, iv, tau[iv]);
    } else if (nv == 6 && p == 0) {
      abaFreeRootBackward(d, i, iv, tau);
    } else if (nv == 6) {
      abaJointBackward<6>(d, i, p, iv, tau);
    } else if (nv == 3) {
      abaJointBackward<3>(d, i, p, iv, tau);
    } else if (nv == 2) {
      abaJointBackward<2>(d, i, p, iv, tau);
    } else if (nv > 0) {
      const auto S = d.S_W.middleCols(iv, nv);
      symmetrizeFromLower(d.IA_W[i]);
      d.U[i].noalias() = d.IA_W[i] * S;
      d.Dinv[i] = (S.transpose() * d.U[i]).inverse();
      d.u[i].noalias() = tau.segment(iv, nv) - S.transpose() * d.PA_W[i];
      if (p == 0) continue;
      const Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, 6, 1> w = d.Dinv[i] * d.u[i];
      d.u[i].noalias() += d.U[i].transpose() * d.A_W[p];
      d.PA_W[p] += d.PA_W[i] + d.U[i] * w;
      d.IA_W[p] += d.IA_W[i];
      d.IA_W[p].noalias() -= d.U[i] * d.Dinv[i] * d.U[i].transpose();
    } else {
      if (p == 0) continue;
      d.PA_W[p] += d.PA_W[i];
      d.IA_W[p] += d.IA_W[i];
    }
  }
  // (U, D, u) => ddq, A_W (including -g); a root's da_parent is zero (its U^T a is not formed).
  // The 1-dof joints carry the previous body's e = a_parent + C and qdd in registers: when body
  // i - 1 is the parent with a 1-dof joint, U . a_p = U . e_p + (U . s_p) qdd_p, so that the
  // chain from one joint's qdd to the next is a multiply-add and D^-1 (the dot products run
  // beside it) instead of the whole a_p, its store and load and a 6-term dot product
  Motion e = Motion::Zero();
  double qddPrev = 0.0;
  bool prevOneDof = false;
  for (int i = 1; i < m.nbodies; ++i) {
    const int nv = m.jointNv[i];
    const int iv = m.idxV[i];
    const int p = m.parent[i];
    const Motion& a = d.A_W[p];
    if (nv == 1) {
      const auto U = d.U[i].col(0);
      double r = d.u[i][0];
      Motion ei;
      if (p == i - 1 && prevOneDof) {
        // (e_p, s_p, qdd_p) => a_p = e_p + s_p qdd_p (A_W[p]'s doubles), U . a_p split
        const Motion sp = d.S_W.col(m.idxV[p]);
        r -= U.dot(e) + U.dot(sp) * qddPrev;
        ei = (e + sp * qddPrev) + d.C_W[i];
      } else {
        if (p != 0) r -= U.dot(a);
        ei = a + d.C_W[i];
      }
      const double qdd = d.Dinv[i](0, 0) * r;
      d.ddq[iv] = qdd;
      d.A_W[i] = ei + d.S_W.col(iv) * qdd;
      e = ei;
      qddPrev = qdd;
      prevOneDof = true;
      continue;
    }
    prevOneDof = false;
    if (nv == 6 && p == 0) {
      abaFreeRootForward(d, i, iv);
    } else if (nv == 6) {
      abaJointForward<6>(d, i, p, iv);
    } else if (nv == 3) {
      abaJointForward<3>(d, i, p, iv);
    } else if (nv == 2) {
      abaJointForward<2>(d, i, p, iv);
    } else if (nv > 0) {
      auto qdd = d.ddq.segment(iv, nv);
      if (p == 0) {
        qdd.noalias() = d.Dinv[i] * d.u[i];
      } else {
        qdd.noalias() = d.Dinv[i] * (d.u[i] - d.U[i].transpose() * a);
      }
      d.A_W[i] = a + d.C_W[i] + d.S_W.middleCols(iv, nv) * qdd;
    } else {
      d.A_W[i] = a + d.C_W[i];
    }
  }
  return d.ddq;
}

}  // namespace

const Eigen::VectorXd& aba(const Model& m, Data& d, const Eigen::VectorXd& q,
                           const Eigen::VectorXd& v, const Eigen::VectorXd& tau,
                           const ExternalForces* fext) {
  YARDSIM_DYNAMICS_CHECK(m, d, q, &v, &tau, "aba");
  return abaPasses<false>(m, d, q, v, tau, fext);
}

const Eigen::VectorXd& abaAfterKinematics(const Model& m, Data& d, const Eigen::VectorXd& q,
                                          const Eigen::VectorXd& v, const Eigen::VectorXd& tau,
                                          const ExternalForces* fext) {
  YARDSIM_DYNAMICS_CHECK(m, d, q, &v, &tau, "abaAfterKinematics");
  return abaPasses<true>(m, d, q, v, tau, fext);
}

}  // namespace yardsim::dynamics
