#include "dynamics/crba.hpp"

#include "dynamics/checks.hpp"
#include "dynamics/flatten.hpp"
#include "dynamics/kinematics.hpp"

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

// (n force columns F_j (6 each, contiguous), motion s) => out_j = F_j . s. With SSE2 two rows
// at a time: per row three products of pairs, the two lanes added at the end for both rows in
// one instruction (the row's sum (f0 s0 + f2 s2 + f4 s4) + (f1 s1 + f3 s3 + f5 s5)).
void columnDots(const double* F, const double* s, int n, double* out) {
#if defined(EIGEN_VECTORIZE_SSE2)
  const __m128d s0 = _mm_loadu_pd(s), s1 = _mm_loadu_pd(s + 2), s2 = _mm_loadu_pd(s + 4);
  // (F_j) => the lanes (f0 s0 + f2 s2 + f4 s4, f1 s1 + f3 s3 + f5 s5)
  const auto lanes = [&](const double* f) {
    return _mm_add_pd(
        _mm_add_pd(_mm_mul_pd(_mm_loadu_pd(f), s0), _mm_mul_pd(_mm_loadu_pd(f + 2), s1)),
        _mm_mul_pd(_mm_loadu_pd(f + 4), s2));
  };
  int j = 0;
  for (; j + 1 < n; j += 2) {
    const __m128d a = lanes(F + 6 * j), b = lanes(F + 6 * j + 6);
    _mm_storeu_pd(out + j, _mm_add_pd(_mm_unpacklo_pd(a, b), _mm_unpackhi_pd(a, b)));
  }
  if (j < n) {
    const __m128d a = lanes(F + 6 * j);
    out[j] = _mm_cvtsd_f64(_mm_add_sd(a, _mm_unpackhi_pd(a, a)));
  }
#else
  const Eigen::Map<const Motion> sm(s);
  for (int j = 0; j < n; ++j) out[j] = Eigen::Map<const Motion>(F + 6 * j).dot(sm);
#endif
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
    placeWithSubspace(m, d, i, q);
    worldCompact(m.inertias[i], m.inertiaDiagonal[i] != 0, d.X_WB[i], d.IC_W[i].data());
    if (d.hasAddedMass[i]) addPointMass(d.addedMass[i](3, 3), d.X_WB[i].p, d.IC_W[i].data());
  }
  // (bodies from the leaves: body i's composite complete, and F of every dof below it) => per
  // dof k of body i F_k = IC_i S_k, then M(j, k) = F_j . S_k for the dofs j of k's subtree (k
  // itself included; Featherstone, RBDA eq. 6.21, world frame: F needs no transform) and
  // M(k, j) = M(j, k); then IC_parent += IC_i. Entries between dofs on different branches are
  // never written (zero from Data).
  const double* F = d.Fcrb.data();
  const double* S = d.S_W.data();
  double* M = d.M.data();
  const Eigen::Index ld = d.M.outerStride();
  for (int i = m.nbodies - 1; i >= 1; --i) {
    const double* k = d.IC_W[i].data();
    const int iv = m.idxV[i];
    for (int c = iv; c < iv + m.jointNv[i]; ++c)
      applyCompact(k, d.S_W.col(c).data(), d.Fcrb.col(c).data());
    for (int c = iv; c < iv + m.jointNv[i]; ++c) {
      const int ns = m.dofSubtree[c];
      double* col = M + c * ld + c;  // M(c.., c)
      columnDots(F + 6 * c, S + 6 * c, ns, col);
      double* row = M + (c + 1) * ld + c;  // M(c, c + 1 ..): ld apart
      for (int j = 1; j < ns; ++j, row += ld) *row = col[j];
    }
    if (m.parent[i] > 0) Compact(d.IC_W[m.parent[i]].data()) += Compact(d.IC_W[i].data());
  }
  return d.M;
}

}  // namespace yardsim::dynamics
