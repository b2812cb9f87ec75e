#pragma once
// The eigenvalues of a dense real matrix through a blocked Hessenberg reduction (the free
// surface's growth check, surface_growth.hpp, on matrices of a few thousand rows). Eigen's
// EigenSolver reduces to Hessenberg form one Householder reflector at a time, two rank-1 updates
// of the whole trailing matrix per column: memory-bound, about 3/4 of the growth check's time on
// the mega-block's free surface (2,040 panels). Here the reflectors of a panel of columns are
// gathered as I - V T V^T (V unit lower trapezoidal, T upper triangular) with Y = A V T, and the
// trailing matrix is updated once per panel by matrix products (the algorithm of LAPACK's
// xGEHRD / xLAHR2: Golub and Van Loan, "Matrix Computations", 4th ed., 7.4.7 and 5.1.7). The
// Hessenberg matrix then goes through the Francis double-shift QR iteration on its active window
// only (EISPACK's hqr): Eigen's RealSchur updates the whole quasi-triangular matrix at every step,
// which a Schur form needs and the eigenvalues do not (about 70 % of the check's time before).
// No units: a matrix in, its eigenvalues out.
#include <Eigen/Core>

namespace yardsim::forces::hydro {

/// (square A, panel width >= 1) => H = Q^T A Q upper Hessenberg (entries below the subdiagonal
/// exactly 0), Q orthogonal (not formed); A is overwritten by H.
void reduceToHessenberg(Eigen::MatrixXd& A, int panel = 32);

/// (square A) => its eigenvalues (complex pairs next to each other, in the order the iteration
/// deflates them): A reduced by reduceToHessenberg, then the windowed Francis QR. Throws
/// std::runtime_error when the QR iteration does not converge (60 iterations on one eigenvalue).
Eigen::VectorXcd eigenvaluesByBlockedHessenberg(Eigen::MatrixXd A);

}  // namespace yardsim::forces::hydro
