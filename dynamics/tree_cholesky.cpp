#include "dynamics/tree_cholesky.hpp"

#include <cmath>

namespace yardsim::dynamics {

bool treeCholeskyFactor(const Eigen::Ref<const Eigen::MatrixXd>& A, std::span<const int> parent,
                        std::span<const int> subtree, Eigen::Ref<Eigen::MatrixXd> L, Eigen::VectorXd& work) {
  const int n = static_cast<int>(A.rows());
  bool ok = true;
  // (A, rows of L below i) => row i of L, from the leaves (i = n - 1) to the root:
  //   L_ii = sqrt(A_ii - |L(sub i, i)|^2),  L_ij = (A_ji - L(sub i, i) . L(sub i, j)) / L_ii
  // for every ancestor j of i, one matrix-vector product per run of consecutive ancestors.
  for (int i = n - 1; i >= 0; --i) {
    const int ns = subtree[i] - 1;
    const auto li = L.col(i).segment(i + 1, ns);
    const double pivot = A(i, i) - li.squaredNorm();
    if (!(pivot > 0.0)) ok = false;
    const double lii = std::sqrt(pivot);
    L(i, i) = lii;
    const double inv = 1.0 / lii;
    for (int hi = parent[i]; hi >= 0;) {
      int lo = hi;  // (parent) => the run lo .. hi of ancestors, each the parent of the next
      while (lo > 0 && parent[lo] == lo - 1) --lo;
      const int len = hi - lo + 1;
      auto w = work.head(len);
      if (ns > 0) {
        w.noalias() = L.block(i + 1, lo, ns, len).transpose() * li;
        L.row(i).segment(lo, len) = (A.col(i).segment(lo, len) - w).transpose() * inv;
      } else {
        L.row(i).segment(lo, len) = A.col(i).segment(lo, len).transpose() * inv;
      }
      hi = parent[lo];
    }
  }
  return ok;
}

void treeCholeskySolveInPlace(const Eigen::Ref<const Eigen::MatrixXd>& L, std::span<const int> subtree,
                              Eigen::Ref<Eigen::VectorXd> x) {
  const int n = static_cast<int>(L.rows());
  // (b) => y = L^-T b, from the leaves: y_i = (b_i - L(sub i, i) . y(sub i)) / L_ii
  for (int i = n - 1; i >= 0; --i) {
    const int ns = subtree[i] - 1;
    double s = x[i];
    if (ns > 0) s -= L.col(i).segment(i + 1, ns).dot(x.segment(i + 1, ns));
    x[i] = s / L(i, i);
  }
  // (y) => x = L^-1 y, from the root: x_i = y_i / L_ii, then y(sub i) -= L(sub i, i) x_i
  for (int i = 0; i < n; ++i) {
    const int ns = subtree[i] - 1;
    x[i] /= L(i, i);
    if (ns > 0) x.segment(i + 1, ns) -= x[i] * L.col(i).segment(i + 1, ns);
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
