#pragma once
// The stiffest mode of a structured system (one with lumped-mass lines) without a dense
// eigen-decomposition: the linearised first-order system J = [0 I; A_q A_v] at (q0, v0) with A_q =
// d(dv/dt)/dq, A_v = d(dv/dt)/dv (1/s^2 and 1/s per m or rad, m/s or rad/s) formed on the
// system's Jacobian pattern by central differences, one pair of stage evaluations per column
// colour (dynamics/integrators/column_colouring.hpp) instead of one per dof, and the eigenvalue of
// largest modulus found by Arnoldi's method with explicit restarts on products with the sparse J
// (scaled as D J D^-1, D = diag(s I, I), s^2 the largest diagonal entry of A_q: the same
// eigenvalues, the stiff modes nearly normal, so that a small Ritz residual means a good value).
// Cost: O(colours + Krylov size) stage evaluations and sparse products, each linear in the nodes,
// where the dense path (stiffness_estimate.cpp) costs 4 nv evaluations and an O(nv^3) eigen-solve.
#include <complex>

#include <Eigen/Core>

#include "dynamics/integrators/column_colouring.hpp"
#include "dynamics/model.hpp"
#include "dynamics/multibody_system.hpp"

namespace yardsim::mechanics {

struct LargestMode {
  std::complex<double> lambda;  // 1/s, the eigenvalue of J of largest modulus
  Eigen::VectorXcd shape;       // its mode's q part (nv, unit norm), the Ritz vector
  double residual = 0.0;        // |J x - lambda x| / |lambda| of the Ritz pair (x of unit norm)
};

// (kernel with its stage connected, q0, v0, pattern of the Jacobian, central-difference step)
// => the largest mode; throws std::runtime_error when an acceleration is not finite
LargestMode largestMode(dynamics::MultibodySystem& kernel, const dynamics::Model& model,
                        const Eigen::VectorXd& q0, const Eigen::VectorXd& v0,
                        const dynamics::JacobianPattern& pattern, double step);

}  // namespace yardsim::mechanics
