// The in-place dense solve behind the mixed problem's solution map: against Eigen's partial-pivot
// LU on random systems of several sizes and column counts, on a system that cannot be solved
// without row interchanges (a zero leading pivot, rows in reverse order), by the residual M X - B,
// and the refusals (a singular matrix, mismatched sizes).
#include <catch2/catch.hpp>

#include <limits>
#include <stdexcept>

#include <Eigen/LU>

#include "forces/hydro/dense_solve.hpp"

using namespace yardsim::forces::hydro;

TEST_CASE("the in-place solve agrees with Eigen's LU and leaves a residual at round-off") {
  for (const int n : {1, 2, 5, 33, 200}) {
    for (const int m : {1, 3, 64}) {
      std::srand(static_cast<unsigned>(100 * n + m));
      const Eigen::MatrixXd M = Eigen::MatrixXd::Random(n, n) + n * Eigen::MatrixXd::Identity(n, n),
                            B = Eigen::MatrixXd::Random(n, m);
      Eigen::MatrixXd factors = M, X = B;
      solveInPlace(factors, X);
      INFO("n " << n << " m " << m);
      const Eigen::MatrixXd reference = M.partialPivLu().solve(B);
      CHECK((X - reference).norm() < 1e-12 * reference.norm());
      CHECK((M * X - B).norm() < 1e-12 * M.norm() * X.norm());
    }
  }
}

TEST_CASE("rows in the wrong order need the interchanges, and get them") {
  // (an anti-diagonal-dominant M: every leading pivot 0 or small without interchanges) => the
  // same solution as the rows in their right order
  const int n = 40;
  std::srand(3);
  Eigen::MatrixXd D = 0.01 * Eigen::MatrixXd::Random(n, n);
  for (int k = 0; k < n; ++k) D(k, k) = 2.0 + k;
  D(0, 0) = 0.0;
  D(0, 1) = 2.0;
  D(1, 0) = 3.0;
  const Eigen::MatrixXd M = D.colwise().reverse(), B = Eigen::MatrixXd::Random(n, 5);
  Eigen::MatrixXd factors = M, X = B;
  solveInPlace(factors, X);
  CHECK((M * X - B).norm() < 1e-12 * M.norm() * X.norm());
  CHECK((X - M.partialPivLu().solve(B)).norm() < 1e-12 * X.norm());
}

TEST_CASE("a singular matrix and mismatched sizes are refused") {
  Eigen::MatrixXd singular = Eigen::MatrixXd::Ones(4, 4), B = Eigen::MatrixXd::Ones(4, 2);
  CHECK_THROWS_AS(solveInPlace(singular, B), std::runtime_error);
  Eigen::MatrixXd M = Eigen::MatrixXd::Identity(3, 3), wrong = Eigen::MatrixXd::Ones(4, 2),
                  notSquare = Eigen::MatrixXd::Ones(3, 4), B3 = Eigen::MatrixXd::Ones(3, 1);
  CHECK_THROWS_AS(solveInPlace(M, wrong), std::invalid_argument);
  CHECK_THROWS_AS(solveInPlace(notSquare, B3), std::invalid_argument);
  // (a NaN in the matrix or the right-hand sides) => refused before LAPACK sees it
  Eigen::MatrixXd withNaN = Eigen::MatrixXd::Identity(3, 3), rhs = Eigen::MatrixXd::Ones(3, 1);
  withNaN(1, 2) = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(solveInPlace(withNaN, rhs), std::invalid_argument);
  Eigen::MatrixXd I = Eigen::MatrixXd::Identity(3, 3);
  rhs(2, 0) = std::numeric_limits<double>::infinity();
  CHECK_THROWS_AS(solveInPlace(I, rhs), std::invalid_argument);
  // (a pivot of 1e-300 against entries of 1e10) => the solution overflows: refused
  Eigen::MatrixXd tiny = Eigen::MatrixXd::Identity(2, 2),
                  big = Eigen::MatrixXd::Constant(2, 1, 1e300);
  tiny(1, 1) = 1e-300;
  CHECK_THROWS_AS(solveInPlace(tiny, big), std::runtime_error);
}
