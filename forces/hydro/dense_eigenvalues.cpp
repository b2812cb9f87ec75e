#include "forces/hydro/dense_eigenvalues.hpp"

#include "forces/hydro/lapack_module.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace yardsim::forces::hydro {

Eigen::VectorXcd denseEigenvalues(Eigen::MatrixXd A) {
  if (A.rows() != A.cols())
    throw std::invalid_argument("denseEigenvalues: the matrix is not square");
  if (!A.allFinite())
    throw std::invalid_argument("denseEigenvalues: the matrix has a NaN or infinite entry");
  const int n = static_cast<int>(A.rows());
  if (n == 0) return {};
  Eigen::VectorXd wr(n), wi(n);
  double unused = 0.0, size = 0.0;
  const int one = 1;
  int info = 0, query = -1;
  const LapackRoutines& la = lapack();
  // (n) => the workspace DGEEV asks for, then the eigenvalues (A is overwritten)
  la.dgeev("N", "N", &n, A.data(), &n, wr.data(), wi.data(), &unused, &one, &unused, &one, &size,
           &query, &info);
  int lwork = std::max(static_cast<int>(size), 3 * n);
  std::vector<double> work(static_cast<std::size_t>(lwork));
  la.dgeev("N", "N", &n, A.data(), &n, wr.data(), wi.data(), &unused, &one, &unused, &one,
           work.data(), &lwork, &info);
  if (info > 0)
    throw std::runtime_error("denseEigenvalues: the QR iteration did not converge (" +
                             std::to_string(info) + " of " + std::to_string(n) +
                             " eigenvalues left)");
  if (info < 0)
    throw std::runtime_error("denseEigenvalues: LAPACK refused argument " + std::to_string(-info));
  Eigen::VectorXcd out(n);
  for (int k = 0; k < n; ++k) out(k) = {wr(k), wi(k)};
  return out;
}

}  // namespace yardsim::forces::hydro
