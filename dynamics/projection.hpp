#pragma once
// Projection onto the loop-constraint manifold: positions by mass-weighted Gauss-Newton
// (dq = -M^-1 J^T (J M^-1 J^T)^-1 g), velocities by the M-orthogonal projection onto J v = 0.

#include <Eigen/Core>

#include "dynamics/data.hpp"
#include "dynamics/model.hpp"

namespace yardsim::dynamics {

/// (q) => q with max |g(q)| <= tol if reached within maxIterations; returns the final max |g|.
double projectPositions(const Model& model, Data& data, Eigen::VectorXd& q, double tol = 1e-12, int maxIterations = 20);
/// (q, v) => v with J(q) v = 0 (M-orthogonal); returns max |J v| after projection.
double projectVelocities(const Model& model, Data& data, const Eigen::VectorXd& q, Eigen::VectorXd& v);

}  // namespace yardsim::dynamics
