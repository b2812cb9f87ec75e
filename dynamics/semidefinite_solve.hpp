#pragma once
// Solves A x = b for a symmetric positive semi-definite A (the Schur complement J M^-1 J^T of
// possibly redundant constraints) by Cholesky with diagonal pivoting: pivots below
// relTol * max diag(A) are dropped and their unknowns set to zero. In place, no allocation.

#include <Eigen/Core>
#include <vector>

namespace yardsim::dynamics {

/// (A, b) => x in b, A overwritten by its partial factor; returns the numerical rank.
int semidefiniteSolve(Eigen::MatrixXd& A, Eigen::VectorXd& b, std::vector<int>& perm, Eigen::VectorXd& work,
                      double relTol = 1e-12);

}  // namespace yardsim::dynamics
