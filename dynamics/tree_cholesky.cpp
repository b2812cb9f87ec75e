#include "dynamics/tree_cholesky.hpp"

#include <cmath>

namespace yardsim::dynamics {

namespace {
// Below this many subtree rows a dot product is a plain loop; from it on one matrix-vector
// product per run of ancestors (Eigen's, vectorised) pays for its set-up.
constexpr int kGemvRows = 12;
}  // namespace

bool treeCholeskyFactor(const Eigen::Ref<const Eigen::MatrixXd>& A, std::span<const int> parent,
                        std::span<const int> subtree, Eigen::Ref<Eigen::MatrixXd> L, Eigen::VectorXd& work) {
  const int n = static_cast<int>(A.rows());
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
    for (int hi = parent[static_cast<std::size_t>(i)]; hi >= 0;) {
      int lo = hi;  // (parent) => the run lo .. hi of ancestors, each the parent of the next
      while (lo > 0 && parent[static_cast<std::size_t>(lo)] == lo - 1) --lo;
      if (ns >= kGemvRows) {
        const int len = hi - lo + 1;
        auto w = work.head(len);
        w.noalias() = L.block(i + 1, lo, ns, len).transpose() * L.col(i).segment(i + 1, ns);
        for (int j = lo; j <= hi; ++j) l[j * ld + i] = (ai[j] - w[j - lo]) * inv;
      } else {
        for (int j = lo; j <= hi; ++j) {
          const double* lj = l + j * ld + i + 1;  // L(sub i, j)
          double s = ai[j];
          for (int k = 0; k < ns; ++k) s -= li[k] * lj[k];
          l[j * ld + i] = s * inv;
        }
      }
      hi = parent[static_cast<std::size_t>(lo)];
    }
  }
  return ok;
}

void treeCholeskySolveInPlace(const Eigen::Ref<const Eigen::MatrixXd>& L, std::span<const int> subtree,
                              Eigen::Ref<Eigen::VectorXd> x) {
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
