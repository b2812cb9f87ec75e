#include "dynamics/tree_cholesky.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <utility>

namespace yardsim::dynamics {

namespace {
// From this many dofs a single chain (a dense matrix) is factorised by Eigen's cache-blocked LLT.
constexpr int kDenseChain = 64;

// (A, the dof tree a single chain: A dense) => L by Eigen's blocked LLT of the reversed matrix:
// with P the reversal, P A P = G G^T gives A = L^T L with L = P G^T P, L(i, j) = G(n-1-j, n-1-i).
// Row by row products stream all of L through the cache once per row, the blocked algorithm does
// not: on the 256-link chain the row by row form took 0.70 of RBDL's time under load, where the
// dense LLT had 0.55.
bool denseChainFactor(const Eigen::Ref<const Eigen::MatrixXd>& A, Eigen::Ref<Eigen::MatrixXd> L) {
  const int n = static_cast<int>(A.rows());
  for (int c = 0; c < n; ++c) {
    for (int r = c; r < n; ++r) L(r, c) = A(n - 1 - r, n - 1 - c);
  }
  const Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>, Eigen::Lower> llt(L);
  // (G in L's lower triangle) => L(i, j) = G(n-1-j, n-1-i): swap each pair of the involution once,
  // in 8 x 8 tiles (the partner of a tile is a tile: both stay in the cache)
  constexpr int kTile = 8;
  for (int J = 0; J < n; J += kTile) {
    for (int I = J; I < n; I += kTile) {
      for (int j = J; j < std::min(J + kTile, n); ++j) {
        for (int i = std::max(I, j); i < std::min(I + kTile, n - 1 - j); ++i)
          std::swap(L(i, j), L(n - 1 - j, n - 1 - i));
      }
    }
  }
  return llt.info() == Eigen::Success;
}

// (pivot p = A_ii - |L(sub i, i)|^2) => L_ii = sqrt(p) at *diag, returns 1 / L_ii: the root and
// the reciprocal of p side by side (sqrt(p) / p), not one after the other
inline double pivotRoot(double p, double* diag) {
  const double lii = std::sqrt(p);
  *diag = lii;
  return lii * (1.0 / p);
}

// (NS subtree rows below row i, L(sub i, i) = li, A(., i) = ai) => L_ii = out[i ld] and L(i, j) =
// out[j ld] for every ancestor j of i, found by walking the parents: L_ii = sqrt(A_ii -
// |L(sub i, i)|^2), L(i, j) = (A_ji - L(sub i, i) . L(sub i, j)) / L_ii; NS fixed at compile time
// (the loops unrolled), the terms subtracted from k = NS - 1 down to 0: L(i + 1, i), written by
// the row just before, enters last (the rows' chain of dependences is one product and one
// subtraction a row shorter per term). Returns whether the pivot is positive.
template <int NS>
bool rowFixed(std::span<const int> parent, int i, const double* li, const double* ai, double* out,
              Eigen::Index ld) {
  double x[NS > 0 ? NS : 1];
  for (int k = 0; k < NS; ++k) x[k] = li[k];
  double pivot = ai[i];
  for (int k = NS - 1; k >= 0; --k) pivot -= x[k] * x[k];
  const double inv = pivotRoot(pivot, out + i * ld);
  for (int j = parent[static_cast<std::size_t>(i)]; j >= 0;
       j = parent[static_cast<std::size_t>(j)]) {
    const double* lj = out + j * ld + 1;  // L(sub i, j)
    double s = ai[j];
    for (int k = NS - 1; k >= 0; --k) s -= x[k] * lj[k];
    out[j * ld] = s * inv;
  }
  return pivot > 0.0;
}

// Eigen's vector register of at most 4 doubles (2 lanes with SSE2, 4 with AVX and AVX-512: its
// 8-lane predux trips GCC 12's -Wuninitialized in the intrinsics' header) for the long dot products
using Packet = Eigen::internal::find_best_packet<double, 4>::type;
constexpr int kLanes = Eigen::internal::unpacket_traits<Packet>::size;
// From this many subtree rows a row's dot products run in vector registers (rowLong);
// below it, one unrolled scalar loop per count of rows (rowFixed), summed term by term
constexpr int kLongRow = 8;
// rowLong takes up to this many consecutive ancestor columns per pass over L(sub i, i)
// (two: four spilled registers in GCC 12's code and cost more instructions)
constexpr int kMaxRun = 2;

// (x of length n, C columns y_c = y0 - c ld) => s_c = x . y_c, C dot products sharing each load
// of x, summed lane by lane in vector registers (Eigen's packets), then the lanes and the tail.
template <int C>
void dotColumns(const double* x, const double* y0, Eigen::Index ld, int n, double* s) {
  namespace ei = Eigen::internal;
  const double* y[C];
  Packet acc[C];
  for (int c = 0; c < C; ++c) {
    y[c] = y0 - c * ld;
    acc[c] = ei::pset1<Packet>(0.0);
  }
  int k = 0;
  for (; k + kLanes <= n; k += kLanes) {
    const Packet xk = ei::ploadu<Packet>(x + k);
    for (int c = 0; c < C; ++c) acc[c] = ei::pmadd(xk, ei::ploadu<Packet>(y[c] + k), acc[c]);
  }
  for (int c = 0; c < C; ++c) {
    double t = ei::predux(acc[c]);
    for (int r = k; r < n; ++r) t += x[r] * y[c][r];
    s[c] = t;
  }
}

// (as rowFixed, any ns) => row i of L, the dot products in vector registers (dotColumns); where
// ancestors run (each the parent of the next: columns ld apart) two ancestor columns share each
// load of L(sub i, i)
bool rowLong(int ns, std::span<const int> parent, int i, const double* li, const double* ai,
             double* out, Eigen::Index ld) {
  double sq = 0.0;
  dotColumns<1>(li, li, 0, ns, &sq);
  const double pivot = ai[i] - sq;
  const double inv = pivotRoot(pivot, out + i * ld);
  for (int j = parent[static_cast<std::size_t>(i)]; j >= 0;) {
    // (j) => the run j, j - 1, ..., j - len + 1 (len <= kMaxRun) and the ancestor after it
    int len = 1, next = parent[static_cast<std::size_t>(j)];
    while (len < kMaxRun && next >= 0 && next == j - len) {
      ++len;
      next = parent[static_cast<std::size_t>(next)];
    }
    const double* y0 = out + j * ld + 1;  // L(sub i, j)
    double s[kMaxRun];
    if (len == 2) {
      dotColumns<2>(li, y0, ld, ns, s);
    } else {
      dotColumns<1>(li, y0, ld, ns, s);
    }
    for (int c = 0; c < len; ++c) out[(j - c) * ld] = (ai[j - c] - s[c]) * inv;
    j = next;
  }
  return pivot > 0.0;
}

// (ns subtree rows, as rowFixed) => row i of L: rowFixed<ns> for ns in NS... (one comparison
// each, inlined), rowLong from kLongRow rows; whether the pivot is positive
template <int... NS>
bool row(std::integer_sequence<int, NS...>, int ns, std::span<const int> parent, int i,
         const double* li, const double* ai, double* out, Eigen::Index ld) {
  bool positive = false;
  const bool fixed =
      ((ns == NS && (positive = rowFixed<NS>(parent, i, li, ai, out, ld), true)) || ...);
  return fixed ? positive : rowLong(ns, parent, i, li, ai, out, ld);
}

// (parent) => whether dof i's parent is i - 1 for every i (one chain: every entry non-zero)
bool singleChain(std::span<const int> parent) {
  for (std::size_t i = 0; i < parent.size(); ++i) {
    if (parent[i] != static_cast<int>(i) - 1) return false;
  }
  return true;
}
}  // namespace

bool treeCholeskyFactor(const Eigen::Ref<const Eigen::MatrixXd>& A, std::span<const int> parent,
                        std::span<const int> subtree, Eigen::Ref<Eigen::MatrixXd> L,
                        [[maybe_unused]] Eigen::VectorXd& work) {
  const int n = static_cast<int>(A.rows());
  if (n >= kDenseChain && singleChain(parent.first(static_cast<std::size_t>(n))))
    return denseChainFactor(A, L);
  const double* a = A.data();
  const Eigen::Index lda = A.outerStride();
  double* l = L.data();
  const Eigen::Index ld = L.outerStride();
  bool ok = true;
  // (A, rows of L below i) => row i of L, from the leaves (i = n - 1) to the root:
  //   L_ii = sqrt(A_ii - |L(sub i, i)|^2),  L_ij = (A_ji - L(sub i, i) . L(sub i, j)) / L_ii
  // for every ancestor j of i (A_ji from A's upper triangle, a column: contiguous).
  for (int i = n - 1; i >= 0; --i) {
    const int ns = subtree[static_cast<std::size_t>(i)] - 1;
    const double* li = l + i * ld + i + 1;  // L(sub i, i)
    const double* ai = a + i * lda;         // A(., i)
    if (!row(std::make_integer_sequence<int, kLongRow>{}, ns, parent, i, li, ai, l + i, ld))
      ok = false;
  }
  return ok;
}

void treeCholeskySolveInPlace(const Eigen::Ref<const Eigen::MatrixXd>& L,
                              std::span<const int> subtree, Eigen::Ref<Eigen::VectorXd> x) {
  const int n = static_cast<int>(L.rows());
  const double* l = L.data();
  const Eigen::Index ld = L.outerStride();
  double* xp = x.data();
  // (b) => y = L^-T b, from the leaves: y_i = (b_i - L(sub i, i) . y(sub i)) / L_ii
  for (int i = n - 1; i >= 0; --i) {
    const int ns = subtree[static_cast<std::size_t>(i)] - 1;
    const double* li = l + i * ld + i + 1;
    double s = xp[i];
    for (int k = 0; k < ns; ++k) s -= li[k] * xp[i + 1 + k];
    xp[i] = s / l[i * ld + i];
  }
  // (y) => x = L^-1 y, from the root: x_i = y_i / L_ii, then y(sub i) -= L(sub i, i) x_i
  for (int i = 0; i < n; ++i) {
    const int ns = subtree[static_cast<std::size_t>(i)] - 1;
    const double* li = l + i * ld + i + 1;
    const double xi = xp[i] / l[i * ld + i];
    xp[i] = xi;
    for (int k = 0; k < ns; ++k) xp[i + 1 + k] -= li[k] * xi;
  }
}

bool choleskyFactor(const Model& m, Data& d) {
  return treeCholeskyFactor(d.M, m.dofParent, m.dofSubtree, d.L, d.cholWork);
}

void choleskySolveInPlace(const Model& m, const Data& d, Eigen::VectorXd& b) {
  treeCholeskySolveInPlace(d.L, m.dofSubtree, b);
}

void choleskySolveInPlace(const Model& m, const Data& d, Eigen::MatrixXd& B) {
  for (Eigen::Index c = 0; c < B.cols(); ++c) treeCholeskySolveInPlace(d.L, m.dofSubtree, B.col(c));
}

}  // namespace yardsim::dynamics
