#include "forces/hydro/dense_solve.hpp"

#include <stdexcept>
#include <string>
#include <vector>

extern "C" {
// LAPACK and BLAS (Fortran calling convention): the LU factorisation with partial pivoting, its
// row interchanges applied to other columns, B <- alpha op(A)^-1 B for a triangular A on the left
void dgetrf_(const int* m, const int* n, double* a, const int* lda, int* ipiv, int* info);
void dlaswp_(const int* n, double* a, const int* lda, const int* k1, const int* k2, const int* ipiv,
             const int* incx);
void dtrsm_(const char* side, const char* uplo, const char* transa, const char* diag, const int* m,
            const int* n, const double* alpha, const double* a, const int* lda, double* b,
            const int* ldb);
}

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
  std::vector<int> pivots(static_cast<std::size_t>(n));
  int info = 0;
  dgetrf_(&n, &n, M.data(), &n, pivots.data(), &info);
  if (info != 0)
    throw std::runtime_error("solveInPlace: the matrix is singular (pivot " + std::to_string(info) +
                             " of " + std::to_string(n) + " is zero)");
  dlaswp_(&m, B.data(), &n, &first, &n, pivots.data(), &first);
  const double one = 1.0;
  dtrsm_("L", "L", "N", "U", &n, &m, &one, M.data(), &n, B.data(), &n);
  dtrsm_("L", "U", "N", "N", &n, &m, &one, M.data(), &n, B.data(), &n);
  if (!B.allFinite())
    throw std::runtime_error(
        "solveInPlace: the solution overflows (the matrix is numerically "
        "singular)");
}

}  // namespace yardsim::forces::hydro
