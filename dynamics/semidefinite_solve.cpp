#include "dynamics/semidefinite_solve.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace yardsim::dynamics {

int semidefiniteSolve(Eigen::MatrixXd& A, Eigen::VectorXd& b, std::vector<int>& perm, Eigen::VectorXd& work,
                      double relTol) {
  const int n = static_cast<int>(A.rows());
  if (n == 0) return 0;
  for (int i = 0; i < n; ++i) perm[i] = i;
  const double tol = relTol * std::max(A.diagonal().maxCoeff(), 0.0);
  // (A) => P A P^T = L L^T on the leading rank x rank block (lower triangle)
  int rank = 0;
  for (int k = 0; k < n; ++k) {
    int p = k;
    for (int i = k + 1; i < n; ++i) {
      if (A(i, i) > A(p, p)) p = i;
    }
    if (!(A(p, p) > tol)) break;
    if (p != k) {
      std::swap(perm[k], perm[p]);
      A.row(k).swap(A.row(p));
      A.col(k).swap(A.col(p));
    }
    const double l = std::sqrt(A(k, k));
    A(k, k) = l;
    for (int i = k + 1; i < n; ++i) A(i, k) /= l;
    for (int j = k + 1; j < n; ++j) {
      for (int i = k + 1; i < n; ++i) A(i, j) -= A(i, k) * A(j, k);  // full trailing block stays symmetric
    }
    rank = k + 1;
  }
  // (L, P b) => x = P^T [L^-T L^-1 (P b)_1; 0]
  for (int i = 0; i < n; ++i) work[i] = b[perm[i]];
  for (int i = 0; i < rank; ++i) {
    double s = work[i];
    for (int k = 0; k < i; ++k) s -= A(i, k) * work[k];
    work[i] = s / A(i, i);
  }
  for (int i = rank - 1; i >= 0; --i) {
    double s = work[i];
    for (int k = i + 1; k < rank; ++k) s -= A(k, i) * work[k];
    work[i] = s / A(i, i);
  }
  for (int i = rank; i < n; ++i) work[i] = 0.0;
  for (int i = 0; i < n; ++i) b[perm[i]] = work[i];
  return rank;
}

}  // namespace yardsim::dynamics
