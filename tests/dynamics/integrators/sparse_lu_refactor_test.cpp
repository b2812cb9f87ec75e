// SparseLuRefactor (sparse_lu_refactor.hpp): a refactorisation on the pattern of the first gives
// the LU that a fresh Eigen SparseLU computes for the same values (the same permutations, the
// same counts, the same solution to the last bit), and solves as a dense LU does, when the values
// change enough for partial pivoting to pick other rows and fill L and U beyond the first
// factorisation; a zero pivot fails and the next matrix factorises; another pattern goes through
// SparseLU::factorize.
#include <catch2/catch.hpp>

#include <Eigen/Dense>
#include <random>
#include <vector>

#include "dynamics/integrators/sparse_lu_refactor.hpp"

using yardsim::dynamics::SparseLuRefactor;
using Matrix = SparseLuRefactor::Matrix;

namespace {

// (n, rng) => a random sparse n x n pattern: the diagonal and about 3 entries a column
std::vector<Eigen::Triplet<double>> randomPattern(int n, std::mt19937& rng) {
  std::uniform_int_distribution<int> row(0, n - 1);
  std::vector<Eigen::Triplet<double>> t;
  for (int j = 0; j < n; ++j) {
    t.emplace_back(j, j, 1.0);
    for (int e = 0; e < 3; ++e) t.emplace_back(row(rng), j, 1.0);
  }
  return t;
}

// (n, pattern, rng, diagonal weight) => the pattern with values: uniform in [-1, 1], plus the
// weight on the diagonal (large: the diagonal pivots; 0: partial pivoting picks rows across it)
Matrix withValues(int n, const std::vector<Eigen::Triplet<double>>& pattern, std::mt19937& rng,
                  double diagonal) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Matrix A(n, n);
  A.setFromTriplets(pattern.begin(), pattern.end(), [](double a, double) { return a; });
  A.makeCompressed();
  for (int j = 0; j < A.outerSize(); ++j)
    for (Matrix::InnerIterator it(A, j); it; ++it)
      it.valueRef() = u(rng) + (it.row() == j ? diagonal : 0.0);
  return A;
}

// (A, its refactorisation) => checked against a fresh SparseLU of A (to the bit) and a dense LU
void checkAgainstFresh(const Matrix& A, SparseLuRefactor& lu) {
  REQUIRE(lu.info() == Eigen::Success);
  Eigen::SparseLU<Matrix, Eigen::COLAMDOrdering<int>> fresh;
  fresh.analyzePattern(A);
  fresh.factorize(A);
  REQUIRE(fresh.info() == Eigen::Success);
  const Eigen::Index n = A.rows();
  CHECK(lu.rowsPermutation().indices() == fresh.rowsPermutation().indices());
  CHECK(lu.colsPermutation().indices() == fresh.colsPermutation().indices());
  CHECK(lu.nnzL() == fresh.nnzL());
  CHECK(lu.nnzU() == fresh.nnzU());
  CHECK(lu.determinant() == fresh.determinant());
  const Eigen::MatrixXd B = Eigen::MatrixXd::Random(n, 4);
  const Eigen::MatrixXd X = lu.solve(B), Y = fresh.solve(B);
  CHECK(X == Y);
  const Eigen::MatrixXd dense = Eigen::MatrixXd(A);
  const Eigen::MatrixXd Z = dense.partialPivLu().solve(B);
  INFO("|X - Z| " << (X - Z).norm() << ", |Z| " << Z.norm());
  CHECK((X - Z).norm() <= 1e-10 * Z.norm());
  CHECK((dense * X - B).norm() <= 1e-10 * X.norm());
}

// (lu, n, pattern, rng, diagonal weight) => a matrix with values, analysed and factorised by lu
Matrix firstFactorisation(SparseLuRefactor& lu, int n,
                          const std::vector<Eigen::Triplet<double>>& pattern, std::mt19937& rng,
                          double diagonal) {
  Matrix A = withValues(n, pattern, rng, diagonal);
  lu.analyzePattern(A);
  lu.refactorize(A);
  return A;
}

}  // namespace

TEST_CASE("a SparseLU refactorisation is the fresh SparseLU of the new values, pivots changed") {
  std::mt19937 rng(11);
  const int n = 60;
  const auto pattern = randomPattern(n, rng);
  SparseLuRefactor lu;
  Matrix A = firstFactorisation(lu, n, pattern, rng, 10.0);
  checkAgainstFresh(A, lu);
  CHECK(lu.fullFactorisations() == 1);
  // (diagonally dominant, then not: partial pivoting picks other rows) => every refactorisation
  // equals the fresh one, none is a full one
  Eigen::VectorXi firstRows = lu.rowsPermutation().indices();
  bool pivotsChanged = false;
  for (int k = 0; k < 8; ++k) {
    A = withValues(n, pattern, rng, k % 2 == 0 ? 0.0 : 10.0);
    lu.refactorize(A);
    checkAgainstFresh(A, lu);
    pivotsChanged = pivotsChanged || lu.rowsPermutation().indices() != firstRows;
  }
  CHECK(pivotsChanged);
  CHECK(lu.fullFactorisations() == 1);
}

TEST_CASE("a refactorisation that fills beyond the first grows L and U as SparseLU does") {
  // (n = 1500, about 4 entries a column: with a dominant diagonal little fill, within SparseLU's
  // first estimate of 20 nnz(A) / n a column; with none partial pivoting picks other rows and L
  // and U fill more) => the refactorisation grows their arrays and still equals the fresh
  // SparseLU; back to the dominant diagonal the grown arrays serve without growing again
  std::mt19937 rng(2);
  const int n = 1500;
  const auto pattern = randomPattern(n, rng);
  SparseLuRefactor lu;
  Matrix A = firstFactorisation(lu, n, pattern, rng, 10.0);
  const Eigen::Index firstL = lu.nnzL();
  A = withValues(n, pattern, rng, 0.0);
  lu.refactorize(A);
  INFO("nnz(L) " << firstL << ", then " << lu.nnzL());
  CHECK(lu.grownFactorisations() == 1);
  checkAgainstFresh(A, lu);
  A = withValues(n, pattern, rng, 10.0);
  lu.refactorize(A);
  CHECK(lu.grownFactorisations() == 1);
  CHECK(lu.fullFactorisations() == 1);
}

TEST_CASE("a zero pivot fails the refactorisation, the next matrix factorises") {
  std::mt19937 rng(5);
  const auto pattern = randomPattern(30, rng);
  SparseLuRefactor lu;
  Matrix A = firstFactorisation(lu, 30, pattern, rng, 10.0);
  REQUIRE(lu.info() == Eigen::Success);
  // (a column of zeros) => singular
  Matrix S = A;
  for (Matrix::InnerIterator it(S, 7); it; ++it) it.valueRef() = 0.0;
  lu.refactorize(S);
  CHECK(lu.info() != Eigen::Success);
  A = withValues(30, pattern, rng, 0.5);
  lu.refactorize(A);
  checkAgainstFresh(A, lu);
  CHECK(lu.fullFactorisations() == 1);
}

TEST_CASE("another pattern goes through SparseLU's own factorisation") {
  std::mt19937 rng(3);
  SparseLuRefactor lu;
  const Matrix A = withValues(20, randomPattern(20, rng), rng, 5.0);
  lu.analyzePattern(A);
  lu.refactorize(A);
  const Matrix B = withValues(20, randomPattern(20, rng), rng, 5.0);
  lu.analyzePattern(B);
  lu.refactorize(B);
  checkAgainstFresh(B, lu);
  CHECK(lu.fullFactorisations() == 2);
}
