#include "forces/hydro/dense_solve.hpp"

#include "forces/hydro/lapack_module.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace yardsim::forces::hydro {

void solveInPlace(Eigen::MatrixXd& M, Eigen::MatrixXd& B) {
  if (M.rows() != M.cols() || B.rows() != M.rows())
    throw std::invalid_argument(
        "solveInPlace: expected a square matrix and as many rows of "
        "right-hand sides (" +
        std::to_string(M.rows()) + " x " + std::to_string(M.cols()) + " and " +
        std::to_string(B.rows()) + " rows)");
  if (!M.allFinite() || !B.allFinite())
    throw std::invalid_argument(
        "solveInPlace: the matrix or the right-hand sides have a NaN or "
        "infinite entry");
  const int n = static_cast<int>(M.rows()), m = static_cast<int>(B.cols()), first = 1;
  if (n == 0 || m == 0) return;
  // (M) => P M = L U in place; (B) => P B, then L^-1, then U^-1
  const LapackRoutines& la = lapack();
  std::vector<int> pivots(static_cast<std::size_t>(n));
  int info = 0;
  la.dgetrf(&n, &n, M.data(), &n, pivots.data(), &info);
  if (info != 0)
    throw std::runtime_error("solveInPlace: the matrix is singular (pivot " + std::to_string(info) +
                             " of " + std::to_string(n) + " is zero)");
  la.dlaswp(&m, B.data(), &n, &first, &n, pivots.data(), &first);
  const double one = 1.0;
  la.dtrsm("L", "L", "N", "U", &n, &m, &one, M.data(), &n, B.data(), &n);
  la.dtrsm("L", "U", "N", "N", &n, &m, &one, M.data(), &n, B.data(), &n);
  if (!B.allFinite())
    throw std::runtime_error(
        "solveInPlace: the solution overflows (the matrix is numerically "
        "singular)");
}

}  // namespace yardsim::forces::hydro
