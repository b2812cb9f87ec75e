// The pivoted Cholesky solve of a semi-definite system: exact on full rank, consistent solutions
// when rows are redundant.
#include <catch2/catch.hpp>

#include <Eigen/Cholesky>

#include "dynamics/semidefinite_solve.hpp"
#include "test_models.hpp"

using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;

TEST_CASE("semidefinite solve: full rank equals LDLT, rank-deficient consistent systems are solved") {
  std::mt19937 rng(24);
  for (int n : {1, 3, 6, 11}) {
    for (int r : {n, std::max(1, n - 2)}) {
      const Eigen::MatrixXd B = Eigen::MatrixXd::Random(n, r);
      const Eigen::MatrixXd A = B * B.transpose() + (r == n ? 0.1 : 0.0) * Eigen::MatrixXd::Identity(n, n);
      const Eigen::VectorXd x0 = randomVectorX(rng, n);
      const Eigen::VectorXd b = A * x0;
      Eigen::MatrixXd F = A;
      Eigen::VectorXd x = b, work(n);
      std::vector<int> perm(static_cast<std::size_t>(n));
      const int rank = semidefiniteSolve(F, x, perm, work);
      CHECK(rank == r);
      CHECK((A * x - b).norm() < 1e-10 * std::max(1.0, b.norm()));
      if (r == n) CHECK((x - A.ldlt().solve(b)).norm() < 1e-10 * x.norm());
    }
  }
  Eigen::MatrixXd Z = Eigen::MatrixXd::Zero(2, 2);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(2), w(2);
  std::vector<int> perm(2);
  CHECK(semidefiniteSolve(Z, b, perm, w) == 0);
  CHECK(b.norm() == 0.0);
}
