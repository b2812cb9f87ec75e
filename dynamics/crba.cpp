#include "dynamics/crba.hpp"

#include "dynamics/checks.hpp"
#include "dynamics/flatten.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/subspace_column.hpp"

#if defined(EIGEN_VECTORIZE_SSE2)
#include <emmintrin.h>
#endif

namespace yardsim::dynamics {

namespace {

// The composite inertia of a subtree as its 10 numbers, in world axes about the world origin:
// k[0] = m (kg), k[1..3] = h = m c (kg m, c the centre of mass), k[4..9] = the rotational inertia
// about the origin (kg m^2) xx, yx, zx, yy, zy, zz. Kept in the first 10 entries of IC_W[i]'s
// storage (Data has no other per-body buffer for it; nothing reads IC_W besides crba).
using Compact = Eigen::Map<Eigen::Matrix<double, 10, 1>>;

// (body inertia, X_WB) => its 10 numbers in world axes about the world origin (the values of
// SpatialInertia::matrixIn, without forming the 6x6 matrix: 10 numbers to sum per body instead of
// 36)
void worldCompact(const SpatialInertia& I, bool diagonal, const Transform& X, double* k) {
  const double* R = X.R.data();  // column-major: R(r, c) = R[r + 3 c]
  const double* b = I.com.data();
  const double c0 = R[0] * b[0] + R[3] * b[1] + R[6] * b[2] + X.p[0];
  const double c1 = R[1] * b[0] + R[4] * b[1] + R[7] * b[2] + X.p[1];
  const double c2 = R[2] * b[0] + R[5] * b[1] + R[8] * b[2] + X.p[2];
  // (R, Ic) => G = R Ic (column-major), then R Ic R^T's lower triangle as rows of G . rows of R
  double G[9];
  if (diagonal) {
    for (int col = 0; col < 3; ++col) {
      const double ic = I.inertiaCom(col, col);
      G[3 * col] = R[3 * col] * ic;
      G[3 * col + 1] = R[3 * col + 1] * ic;
      G[3 * col + 2] = R[3 * col + 2] * ic;
    }
  } else {
    const double* J = I.inertiaCom.data();
    for (int col = 0; col < 3; ++col) {
      for (int r = 0; r < 3; ++r)
        G[r + 3 * col] = R[r] * J[3 * col] + R[r + 3] * J[3 * col + 1] + R[r + 6] * J[3 * col + 2];
    }
  }
  const auto gr = [&](int r, int s) {
    return G[r] * R[s] + G[r + 3] * R[s + 3] + G[r + 6] * R[s + 6];
  };
  const double m = I.mass, mc2 = m * (c0 * c0 + c1 * c1 + c2 * c2);
  k[0] = m;
  k[1] = m * c0;
  k[2] = m * c1;
  k[3] = m * c2;
  k[4] = gr(0, 0) + (mc2 - m * c0 * c0);
  k[5] = gr(1, 0) - m * c1 * c0;
  k[6] = gr(2, 0) - m * c2 * c0;
  k[7] = gr(1, 1) + (mc2 - m * c1 * c1);
  k[8] = gr(2, 1) - m * c2 * c1;
  k[9] = gr(2, 2) + (mc2 - m * c2 * c2);
}

// (added mass A, [angular; linear] about the body origin) => whether A is a point mass there:
// dm 1 in the linear block and zero elsewhere (mechanics::followMass's share of a winched rope's
// node), which the 10 numbers can carry
bool pointAddedMass(const Matrix6& A) {
  const double dm = A(3, 3);
  for (int c = 0; c < 6; ++c) {
    for (int r = 0; r < 6; ++r) {
      if (A(r, c) != (r == c && r >= 3 ? dm : 0.0)) return false;
    }
  }
  return true;
}

// (10 numbers k, point mass dm at the world position p) => k + its 10 numbers
void addPointMass(double dm, const Vector3& p, double* k) {
  const double p2 = dm * p.squaredNorm();
  k[0] += dm;
  k[1] += dm * p.x();
  k[2] += dm * p.y();
  k[3] += dm * p.z();
  k[4] += p2 - dm * p.x() * p.x();
  k[5] -= dm * p.y() * p.x();
  k[6] -= dm * p.z() * p.x();
  k[7] += p2 - dm * p.y() * p.y();
  k[8] -= dm * p.z() * p.y();
  k[9] += p2 - dm * p.z() * p.z();
}

// (10 numbers k, motion s = (w, v)) => f = k s = (I_o w + h x v, m v - h x w)
void applyCompact(const double* k, const double* s, double* f) {
  const double w0 = s[0], w1 = s[1], w2 = s[2], v0 = s[3], v1 = s[4], v2 = s[5];
  const double h0 = k[1], h1 = k[2], h2 = k[3];
  f[0] = k[4] * w0 + k[5] * w1 + k[6] * w2 + (h1 * v2 - h2 * v1);
  f[1] = k[5] * w0 + k[7] * w1 + k[8] * w2 + (h2 * v0 - h0 * v2);
  f[2] = k[6] * w0 + k[8] * w1 + k[9] * w2 + (h0 * v1 - h1 * v0);
  f[3] = k[0] * v0 - (h1 * w2 - h2 * w1);
  f[4] = k[0] * v1 - (h2 * w0 - h0 * w2);
  f[5] = k[0] * v2 - (h0 * w1 - h1 * w0);
}

// (force f of dof c, S_W, the dof tree) => M(c, a) = M(a, c) = f . S_a for a = c and every
// ancestor dof a >= stop of c (returns the first ancestor below stop, or -1), each summed as (f0 s0
// + f2 s2 + f4 s4) + (f1 s1 + f3 s3 + f5 s5) (with SSE2 the two sums are the lanes of one register,
// f held in three registers across the ancestors)
int rowOfM(const double* f, const double* S, const int* dofParent, int c, int stop, double* M,
           Eigen::Index ld) {
  double* rowC = M + c;       // M(c, a) = rowC[a ld]
  double* colC = M + c * ld;  // M(a, c) = colC[a]
#if defined(EIGEN_VECTORIZE_SSE2)
  // (f just written entry by entry by applyCompact) => its pairs from 8-byte loads: a 16-byte load
  // of two fresh 8-byte stores waits for them to drain instead of being forwarded
  const __m128d f0 = _mm_set_pd(f[1], f[0]), f1 = _mm_set_pd(f[3], f[2]),
                f2 = _mm_set_pd(f[5], f[4]);
  int a = c;
  for (; a >= stop; a = dofParent[a]) {
    const double* s = S + 6 * a;
    const __m128d t =
        _mm_add_pd(_mm_add_pd(_mm_mul_pd(f0, _mm_loadu_pd(s)), _mm_mul_pd(f1, _mm_loadu_pd(s + 2))),
                   _mm_mul_pd(f2, _mm_loadu_pd(s + 4)));
    const double v = _mm_cvtsd_f64(_mm_add_sd(t, _mm_unpackhi_pd(t, t)));
    rowC[a * ld] = v;
    colC[a] = v;
  }
#else
  int a = c;
  for (; a >= stop; a = dofParent[a]) {
    const double* s = S + 6 * a;
    const double v =
        ((f[0] * s[0] + f[2] * s[2]) + f[4] * s[4]) + ((f[1] * s[1] + f[3] * s[3]) + f[5] * s[5]);
    rowC[a * ld] = v;
    colC[a] = v;
  }
#endif
  return a;
}

// (force f = (n, f) of dof c, in world axes about the world origin; R, p of X_WB of a free-joint
// body whose dofs are 0 .. 5) => M(c, j) = M(j, c) = S_j . f for j = 0 .. 5: with S = 1 in the
// body frame, f in the body frame about its origin, (R^T (n - p x f), R^T f): one force transform
// instead of six 6-entry products
inline void freeRootRow(const double* f, const double* R, const double* p, int c, double* M,
                        Eigen::Index ld) {
  const double p0 = p[0], p1 = p[1], p2 = p[2];
  const double t0 = f[0] - (p1 * f[5] - p2 * f[4]);
  const double t1 = f[1] - (p2 * f[3] - p0 * f[5]);
  const double t2 = f[2] - (p0 * f[4] - p1 * f[3]);
  double* row = M + c;       // M(c, j) = row[j ld]
  double* col = M + c * ld;  // M(j, c) = col[j]
  for (int j = 0; j < 3; ++j) {
    const double* r = R + 3 * j;  // column-major: R^T's row j is R's column j
    const double nB = r[0] * t0 + r[1] * t1 + r[2] * t2;
    const double fB = r[0] * f[3] + r[1] * f[4] + r[2] * f[5];
    row[j * ld] = col[j] = nB;
    row[(j + 3) * ld] = col[j + 3] = fB;
  }
}

// Where the free root's rows are formed: after the loop over the bodies, all at once (F_c kept in
// Fcrb, R and p loaded once), or per dof right after its row of M (an out-of-line call). Measured
// at tree 9 (docs/performance_peers.md, crba31): after the loop 0.96 of the per-dof time with SSE2
// code, but 1.11 with AVX (-march=native), where the per-dof form is kept.
#if defined(__AVX__)
constexpr bool kRootRowsAfter = false;
#else
constexpr bool kRootRowsAfter = true;
#endif

// (f of dof c, X_WB of the free root) => freeRootRow, out of line (the per-dof form; unused where
// kRootRowsAfter)
[[gnu::noinline, maybe_unused]] void freeRootRowCall(const double* f, const Transform& X, int c,
                                                     double* M, Eigen::Index ld) {
  freeRootRow(f, X.R.data(), X.p.data(), c, M, ld);
}

// (F_c of dofs c = 6 .. end - 1, end - 1 the free root's subtree's last dof) => freeRootRow for
// each
[[gnu::noinline]] void freeRootRows(const double* F, const Transform& X, int end, double* M,
                                    Eigen::Index ld) {
  for (int c = 6; c < end; ++c) freeRootRow(F + 6 * c, X.R.data(), X.p.data(), c, M, ld);
}

// (the composite of a free-joint body whose dofs are 0 .. 5 as 10 numbers in world axes about the
// world origin, its X_WB) => M's 6x6 block of those dofs: the composite in the body frame about its
// origin, [I_B, [h_B]x; -[h_B]x, m 1] (S = 1)
[[gnu::noinline]] void freeRootBlock(const double* k, const Transform& X, double* M,
                                     Eigen::Index ld) {
  // on plain doubles, entry by entry in the order of Eigen's expressions (the same doubles): a
  // small matrix written entry by entry and then copied by 16-byte loads waits for its stores
  const double mass = k[0];
  const double h[3] = {k[1], k[2], k[3]};
  const double p[3] = {X.p[0], X.p[1], X.p[2]};
  const double* R = X.R.data();  // column-major: R(r, c) = R[r + 3 c]
  // (about the world origin) => about p: I - 2 (p . h) 1 + (p h^T + h p^T) + m (p . p 1 - p p^T)
  const double ph = (p[0] * h[0] + p[1] * h[1]) + p[2] * h[2];
  const double pp = (p[0] * p[0] + p[1] * p[1]) + p[2] * p[2];
  const double shift = mass * pp - 2.0 * ph;
  const double k3[3][3] = {{k[4], k[5], k[6]}, {k[5], k[7], k[8]}, {k[6], k[8], k[9]}};
  double I[3][3];  // I[r][c]
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) {
      I[r][c] = k3[r][c] + ((p[r] * h[c] + p[c] * h[r]) - mass * (p[r] * p[c]));
    }
    I[c][c] += shift;
  }
  // (R, I) => T = R^T I, then IB = T R (each entry's three terms summed in order)
  double T[3][3], IB[3][3];
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c)
      T[r][c] = (R[3 * r] * I[0][c] + R[3 * r + 1] * I[1][c]) + R[3 * r + 2] * I[2][c];
  }
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c)
      IB[r][c] = (T[r][0] * R[3 * c] + T[r][1] * R[3 * c + 1]) + T[r][2] * R[3 * c + 2];
  }
  // (h, p) => hB = R^T (h - m p)
  const double g[3] = {h[0] - mass * p[0], h[1] - mass * p[1], h[2] - mass * p[2]};
  double hB[3];
  for (int r = 0; r < 3; ++r) hB[r] = (R[3 * r] * g[0] + R[3 * r + 1] * g[1]) + R[3 * r + 2] * g[2];
  // (IB, hB, m) => M's 6x6 block [IB, [hB]x; -[hB]x, m 1]: IB's lower triangle mirrored
  const auto at = [&](int r, int c) -> double& { return M[r + c * ld]; };
  for (int c = 0; c < 3; ++c) {
    for (int r = c; r < 3; ++r) at(r, c) = at(c, r) = IB[r][c];
  }
  const double hx[3][3] = {{0.0, -hB[2], hB[1]}, {hB[2], 0.0, -hB[0]}, {-hB[1], hB[0], 0.0}};
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) {
      at(r, 3 + c) = hx[r][c];
      at(3 + r, c) = hx[c][r];
      at(3 + r, 3 + c) = r == c ? mass : 0.0;
    }
  }
}

// (X_WB, S_W, each body's 10 numbers in IC_W; FreeRoot: body 1 on a free joint at the world) =>
// M, IC_W the composites. From the leaves (body i's composite complete when reached): per dof c of
// body i F_c = IC_i S_c, then M(c, a) = M(a, c) = F_c . S_a for a = c and every ancestor dof a of c
// (Featherstone, RBDA eq. 6.21, world frame: F needs no transform; S_a of every dof is known from
// the placement); then IC_parent += IC_i. Entries between dofs on different branches are never
// written (zero from Data).
template <bool FreeRoot>
void compositesAndM(const Model& m, Data& d) {
  const double* S = d.S_W.data();
  double* M = d.M.data();
  const Eigen::Index ld = d.M.outerStride();
  const int* dofParent = m.dofParent.data();
  double* F = d.Fcrb.data();  // F_c = IC S_c, kept for the free root's rows
  constexpr int stop = FreeRoot ? 6 : 0;
  for (int i = m.nbodies - 1; i >= 1; --i) {
    const double* k = d.IC_W[i].data();
    if (FreeRoot && i == 1) {
      freeRootBlock(k, d.X_WB[1], M, ld);
      if constexpr (kRootRowsAfter) freeRootRows(F, d.X_WB[1], m.dofSubtree[0], M, ld);
      return;
    }
    const int iv = m.idxV[i], end = iv + m.jointNv[i];
    for (int c = iv; c < end; ++c) {
      double local[6];
      double* f = FreeRoot && kRootRowsAfter ? F + 6 * c : local;
      applyCompact(k, S + 6 * c, f);
      const int a = rowOfM(f, S, dofParent, c, stop, M, ld);
      if constexpr (FreeRoot && !kRootRowsAfter) {
        if (a >= 0) freeRootRowCall(f, d.X_WB[1], c, M, ld);
      }
    }
    if (m.parent[i] > 0) Compact(d.IC_W[m.parent[i]].data()) += Compact(d.IC_W[i].data());
  }
}

// (q) => X_WB, S_W of body i (the shortcuts of RNEA and ABA for coordinate-axis joints, equal in
// value to the general products)
void placeWithSubspace(const Model& m, Data& d, int i, const Eigen::VectorXd& q) {
  placeBody(m, d, i, q);
  if (m.jointNv[i] == 1) {
    d.S_W.col(m.idxV[i]) = worldSubspaceColumn(m, d, i);
  } else {
    for (int k = 0; k < m.jointNv[i]; ++k)
      d.S_W.col(m.idxV[i] + k) = d.X_WB[i].actMotion(d.S[i].col(k));
  }
}

// (X_WB of the parent P, the joint frame's origin o in P, axis K, cos c and sin s of a revolute
// joint's angle) => X_WB of the body and its S_W column (R_WB's column K; p x it): the doubles of
// placeBody and worldSubspaceColumn (R_PB(K, K) as the joint's formula rounds it, o + 0 as X_PB.p,
// each row's terms in Eigen's order), without writing X_PB
template <int K>
void placeRevoluteWorld(const Transform& P, const Vector3& o, double c, double s, Transform& X,
                        double* sw) {
  constexpr int a = (K + 1) % 3;
  constexpr int b = (K + 2) % 3;
  const double* pr = P.R.data();
  double* r = X.R.data();
  const double o0 = o[0] + 0.0, o1 = o[1] + 0.0, o2 = o[2] + 0.0;
  for (int row = 0; row < 3; ++row)
    X.p[row] = P.p[row] + ((pr[row] * o0 + pr[row + 3] * o1) + pr[row + 6] * o2);
  const double kk = c + (1.0 - c), sPos = 0.0 + s, sNeg = 0.0 - s;
  for (int row = 0; row < 3; ++row) {
    r[row + 3 * K] = pr[row + 3 * K] * kk;
    r[row + 3 * a] = pr[row + 3 * a] * c + pr[row + 3 * b] * sPos;
    r[row + 3 * b] = pr[row + 3 * a] * sNeg + pr[row + 3 * b] * c;
  }
  coordinateAxisSubspace(true, r + 3 * K, X.p.data(), sw);
}

// (q, body i on a free joint: S = 1) => X_WB of body i (placeBody) and its six columns of S_W,
// [R 0; p x R R] column by column (not X_WB S's products)
[[gnu::noinline]] void placeFree(const Model& m, Data& d, int i, const Eigen::VectorXd& q) {
  placeBody(m, d, i, q);
  const Transform& X = d.X_WB[i];
  double* sw = d.S_W.data() + 6 * m.idxV[i];
  for (int c = 0; c < 3; ++c, sw += 6) {
    const Eigen::Map<const Vector3> r(X.R.data() + 3 * c);
    Eigen::Map<Motion> rot(sw), lin(sw + 18);  // the columns of dofs c and c + 3
    rot << r, X.p.cross(r);
    lin << Vector3::Zero(), r;
  }
}

// (angle) => sinCos (the same doubles). With AVX out of line: inlined into the placement loop it
// made native code 1.15-1.18 times as slow at tree 9 and 1.10 at tree 33 (and 0.90 at chain 8);
// with SSE2 inline (out of line 1.02-1.03 times as slow). docs/performance_peers.md, fifteenth
// session (lead).
#if defined(__AVX__)
[[gnu::noinline]] void crbaSinCos(double angle, double& s, double& c) {
  sinCos(angle, s, c);
}
#else
inline void crbaSinCos(double angle, double& s, double& c) {
  sinCos(angle, s, c);
}
#endif

// (q) => X_WB of body i and its columns of S_W: coordinate-axis revolute and prismatic joints in
// translated frames directly (X_PB not written), any other joint by placeBody
void placeForCrba(const Model& m, Data& d, int i, const Eigen::VectorXd& q) {
  const int k = m.jointAxis[i];
  if (k < 0 || m.placementRotated[i] != 0) {
    if (m.joints[i].type != JointType::Free) {
      placeWithSubspace(m, d, i, q);
      return;
    }
    placeFree(m, d, i, q);
    return;
  }
  const Transform& P = d.X_WB[m.parent[i]];
  Transform& X = d.X_WB[i];
  double* sw = d.S_W.data() + 6 * m.idxV[i];
  const double qi = q[m.idxQ[i]];
  if (m.joints[i].type == JointType::Revolute) {
    double s = 0.0, c = 0.0;
    crbaSinCos(qi, s, c);
    if (k == 0) {
      placeRevoluteWorld<0>(P, m.X_PJ[i].p, c, s, X, sw);
    } else if (k == 1) {
      placeRevoluteWorld<1>(P, m.X_PJ[i].p, c, s, X, sw);
    } else {
      placeRevoluteWorld<2>(P, m.X_PJ[i].p, c, s, X, sw);
    }
    return;
  }
  // (prismatic) => R_WB = R_WP, p_WB = p_WP + R_WP (o + e_K q), S_W = (0, R_WB's column K)
  const Vector3 t = m.X_PJ[i].p + m.joints[i].axis * qi;
  X.p = P.p + P.R * t;
  X.R = P.R;
  coordinateAxisSubspace(false, X.R.data() + 3 * k, X.p.data(), sw);
}

// (q, added mass on some body) => M with the composite inertias as 6x6 matrices (an added mass is
// a general symmetric 6x6, not a rigid body's 10 numbers)
void crbaMatrices(const Model& m, Data& d, const Eigen::VectorXd& q) {
  // (q) => X_WB, S_W, IC_W = X_WB^* (I + A) X_WB^-1 (A: added mass)
  for (int i = 1; i < m.nbodies; ++i) {
    placeWithSubspace(m, d, i, q);
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
}

}  // namespace

// flatten (YARDSIM_FLATTEN): inline every Eigen helper (GCC otherwise leaves small products as
// calls)
YARDSIM_FLATTEN const Eigen::MatrixXd& crba(const Model& m, Data& d, const Eigen::VectorXd& q) {
  YARDSIM_DYNAMICS_CHECK(m, d, q, nullptr, nullptr, "crba");
  for (int i = 1; i < m.nbodies; ++i) {
    if (d.hasAddedMass[i] && !pointAddedMass(d.addedMass[i])) {
      crbaMatrices(m, d, q);
      return d.M;
    }
  }
  // (q) => X_WB, S_W and each body's inertia (and added point mass) as 10 numbers in world axes
  // about the world origin
  for (int i = 1; i < m.nbodies; ++i) {
    placeForCrba(m, d, i, q);
    worldCompact(m.inertias[i], m.inertiaDiagonal[i] != 0, d.X_WB[i], d.IC_W[i].data());
    if (d.hasAddedMass[i]) addPointMass(d.addedMass[i](3, 3), d.X_WB[i].p, d.IC_W[i].data());
  }
  // a floating base (body 1 on a free joint at the world: dofs 0 .. 5, S = 1) takes its 6x6 block
  // from its composite and each row below it from one force transform (freeRootBlock, freeRootRow)
  if (m.nbodies > 1 && m.parent[1] == 0 && m.joints[1].type == JointType::Free && m.idxV[1] == 0) {
    compositesAndM<true>(m, d);
  } else {
    compositesAndM<false>(m, d);
  }
  return d.M;
}

}  // namespace yardsim::dynamics
