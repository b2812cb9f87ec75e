// The bordered band LU against Eigen's dense partial-pivot LU: a band matrix of 3-dof nodes with
// a few border dofs scattered through it (the shape of lumped lines on rigid bodies) is found,
// its band and border are the expected ones, and its solves equal the dense ones, also where the
// band needs row interchanges (zero diagonal entries) and after new values on the same structure;
// a matrix without that shape is refused, and a singular one is reported.
#include <catch2/catch.hpp>

#include <Eigen/LU>
#include <cmath>
#include <random>
#include <vector>

#include "dynamics/integrators/bordered_band_lu.hpp"

using yardsim::dynamics::BorderedBandLu;

namespace {

// (n, band half-width, border dofs, seed, zeroDiagonal) => a random matrix: entries within the
// band, the border dofs coupled to every 17th dof (far from them) and to each other; the diagonal
// dominant unless zeroDiagonal, which empties every 7th diagonal entry of the band (pivoting)
Eigen::SparseMatrix<double> bordered(int n, int w, const std::vector<int>& border, unsigned seed,
                                     bool zeroDiagonal) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Eigen::Triplet<double>> t;
  auto isBorder = [&](int i) {
    for (int b : border)
      if (b == i) return true;
    return false;
  };
  for (int j = 0; j < n; ++j) {
    if (isBorder(j)) continue;
    for (int i = std::max(0, j - w); i <= std::min(n - 1, j + w); ++i) {
      if (isBorder(i)) continue;
      double a = u(rng);
      if (i == j) a = zeroDiagonal && j % 7 == 3 ? 0.0 : 4.0 * w + a;
      t.emplace_back(i, j, a);
    }
  }
  for (int b : border) {
    t.emplace_back(b, b, 10.0 + u(rng));
    for (int j = 5; j < n; j += 17)
      if (!isBorder(j)) {
        t.emplace_back(b, j, u(rng));
        t.emplace_back(j, b, u(rng));
      }
    for (int c : border)
      if (c != b) t.emplace_back(b, c, u(rng));
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  return A;
}

// (A, b) => the bordered band solve's distance from the dense LU's, relative
double solveError(const BorderedBandLu& lu, const Eigen::SparseMatrix<double>& A,
                  const Eigen::VectorXd& b) {
  Eigen::VectorXd x;
  lu.solve(b, x);
  const Eigen::VectorXd ref = Eigen::MatrixXd(A).partialPivLu().solve(b);
  return (x - ref).norm() / ref.norm();
}

}  // namespace

TEST_CASE("bordered band LU: finds the band and the border, solves as the dense LU") {
  const int n = 300, w = 5;
  const std::vector<int> border{0, 1, 150, 299};
  const Eigen::SparseMatrix<double> A = bordered(n, w, border, 7u, false);
  BorderedBandLu lu;
  REQUIRE(lu.analyse(A));
  CHECK(lu.bandwidth() == w);
  CHECK(lu.border() == 4);
  REQUIRE(lu.factorise(A));
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -2.0, 3.0);
  CHECK(solveError(lu, A, b) < 1e-12);
  // (new values on the same structure) => factorised again, the new solution
  Eigen::SparseMatrix<double> A2 = A;
  for (int k = 0; k < A2.nonZeros(); ++k) A2.valuePtr()[k] *= 1.0 + 0.1 * std::sin(k);
  REQUIRE(lu.factorise(A2));
  CHECK(solveError(lu, A2, b) < 1e-12);
}

TEST_CASE("bordered band LU: row interchanges where the band's diagonal is zero") {
  const int n = 120, w = 4;
  const Eigen::SparseMatrix<double> A = bordered(n, w, {60}, 11u, true);
  BorderedBandLu lu;
  REQUIRE(lu.analyse(A));
  REQUIRE(lu.factorise(A));
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(n);
  CHECK(solveError(lu, A, b) < 1e-10);
  // (no border: a plain band matrix) => the same
  const Eigen::SparseMatrix<double> B = bordered(n, w, {}, 12u, true);
  REQUIRE(lu.analyse(B));
  CHECK(lu.border() == 0);
  REQUIRE(lu.factorise(B));
  CHECK(solveError(lu, B, b) < 1e-10);
}

TEST_CASE("bordered band LU: a matrix without the shape is refused, a singular one reported") {
  // (every dof coupled to one 40 places away: a border of half the matrix) => refused
  const int n = 200;
  std::vector<Eigen::Triplet<double>> t;
  for (int j = 0; j < n; ++j) {
    t.emplace_back(j, j, 4.0);
    t.emplace_back((j + 40) % n, j, 1.0);
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  BorderedBandLu lu;
  CHECK_FALSE(lu.analyse(A, 12, 64));
  // (a column of zeros) => singular: a zero pivot, and factorise says so
  Eigen::SparseMatrix<double> S = bordered(60, 3, {30}, 5u, false);
  Eigen::MatrixXd dense(S);
  dense.col(20).setZero();
  S = dense.sparseView();
  S.makeCompressed();
  REQUIRE(lu.analyse(S));
  CHECK_FALSE(lu.factorise(S));
}
