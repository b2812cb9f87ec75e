#pragma once
// The eigenvalues of a dense real matrix of a few thousand rows (the free surface's growth check,
// surface_growth.hpp) through LAPACK's DGEEV without eigenvectors: balancing, the blocked
// Hessenberg reduction (DGEHRD) and the small-bulge multishift QR with aggressive early deflation
// (DHSEQR; Braman, Byers and Mathias 2002). Linked against OpenBLAS's LAPACK (scripts/setup.sh,
// libopenblas-dev), which runs the Hessenberg reduction's matrix products on the machine's vector
// units and on its cores (OPENBLAS_NUM_THREADS caps them). At 3,000 rows in one thread it takes
// about a quarter of the CPU of a double-shift Francis QR after Eigen's kernels (docs/
// hydrodynamics.md, "Limits of the time-domain solver").
// No units: a matrix in, its eigenvalues out.
#include <Eigen/Core>

namespace yardsim::forces::hydro {

/// (square A) => its eigenvalues (complex pairs next to each other, the positive imaginary part
/// first, in LAPACK's order). Throws std::invalid_argument for a matrix that is not square or has
/// a NaN or infinite entry, and
/// std::runtime_error when the QR iteration does not converge (LAPACK's INFO > 0).
Eigen::VectorXcd denseEigenvalues(Eigen::MatrixXd A);

}  // namespace yardsim::forces::hydro
