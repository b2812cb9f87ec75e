#pragma once
// The configuration at which a system at rest stays at rest: accelerations zero with v = 0,
// found by Newton's method in the tangent space of the configuration manifold (joint-aware
// increments, quaternions stay unit) with a finite-difference Jacobian and a backtracking line
// search. Used to start a scene in static equilibrium (a block hanging still on its ropes)
// instead of releasing it from the unstretched geometry.

#include <Eigen/Core>

#include "dynamics/integrators/integrator.hpp"
#include "dynamics/model.hpp"

namespace yardsim::dynamics {

struct EquilibriumOptions {
  double tolerance = 1e-9;   // on max |a| (m/s^2 or rad/s^2)
  int maxIterations = 50;
  double step = 1e-7;        // finite-difference increment in tangent coordinates
  int maxNeutralSteps = 20;  // moves in a row that leave the residual as it is (a fall onto slack ropes)
};

struct EquilibriumResult {
  bool converged = false;
  int iterations = 0;
  double residual = 0.0;  // max |a| at the returned configuration
};

/// (model, accelerations of the system with its forces, t, q) => q moved to static equilibrium.
/// Directions with no stiffness (a free slide) are left where they are (minimum-norm steps).
EquilibriumResult solveStaticEquilibrium(const Model& model, AccelerationSource& system, double t,
                                         Eigen::VectorXd& q, const EquilibriumOptions& options = {});

}  // namespace yardsim::dynamics
