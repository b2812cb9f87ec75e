#pragma once
// A dense square system with many right-hand sides, solved in place through LAPACK and BLAS
// (OpenBLAS): the LU factorisation with partial pivoting (DGETRF), its row interchanges applied
// to the right-hand sides (DLASWP), then the unit lower and the upper triangular solves (DTRSM).
// The time-domain Rankine solver's mixed problem forms its solution map M^-1 R with it
// (mixed_problem.hpp). No units: matrices in, a matrix out.
#include <Eigen/Core>

namespace yardsim::forces::hydro {

/// (square M, n x m right-hand sides B) => B overwritten by M^-1 B, M by its LU factors (P M = L
/// U). Throws std::invalid_argument for mismatched sizes or a NaN or infinite entry, and
/// std::runtime_error naming the pivot when M is singular (or when the solution overflows).
void solveInPlace(Eigen::MatrixXd& M, Eigen::MatrixXd& B);

}  // namespace yardsim::forces::hydro
