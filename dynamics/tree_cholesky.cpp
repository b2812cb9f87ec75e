#include "dynamics/tree_cholesky.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <utility>

namespace yardsim::dynamics {

namespace {
// Below this many subtree rows a dot product is a plain loop; from it on one matrix-vector
// product per run of ancestors (Eigen's, vectorised) pays for its set-up.
constexpr int kGemvRows = 12;
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
                        Eigen::VectorXd& work) {
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
    double pivot = ai[i];
    for (int k = 0; k < ns; ++k) pivot -= li[k] * li[k];
    if (!(pivot > 0.0)) ok = false;
    const double lii = std::sqrt(pivot);
    l[i * ld + i] = lii;
    const double inv = 1.0 / lii;
    if (ns < kGemvRows) {
      // (few subtree rows) => one dot product per ancestor j, found by walking the parents
      for (int j = parent[static_cast<std::size_t>(i)]; j >= 0;
           j = parent[static_cast<std::size_t>(j)]) {
        const double* lj = l + j * ld + i + 1;  // L(sub i, j)
        double s = ai[j];
        for (int k = 0; k < ns; ++k) s -= li[k] * lj[k];
        l[j * ld + i] = s * inv;
      }
      continue;
    }
    for (int hi = parent[static_cast<std::size_t>(i)]; hi >= 0;) {
      int lo = hi;  // (parent) => the run lo .. hi of ancestors, each the parent of the next
      while (lo > 0 && parent[static_cast<std::size_t>(lo)] == lo - 1) --lo;
      const int len = hi - lo + 1;
      auto w = work.head(len);
      w.noalias() = L.block(i + 1, lo, ns, len).transpose() * L.col(i).segment(i + 1, ns);
      for (int j = lo; j <= hi; ++j) l[j * ld + i] = (ai[j] - w[j - lo]) * inv;
      hi = parent[static_cast<std::size_t>(lo)];
    }
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
