#pragma once
// Forward dynamics of a tree closed by loop constraints, with Lagrange multipliers solved through
// the Schur complement:  M ddq + h = tau + J^T lambda,  J ddq = -kappa - 2 alpha (J v) - beta^2 g(q).
// The Baumgarte terms (alpha, beta) are off by default; position and velocity projection are the
// other way to stay on the constraint manifold (projection.hpp).

#include <Eigen/Core>

#include "dynamics/data.hpp"
#include "dynamics/external_forces.hpp"
#include "dynamics/model.hpp"

namespace yardsim::dynamics {

struct Baumgarte {
  double alpha = 0.0;  ///< velocity feedback [1/s]
  double beta = 0.0;   ///< position feedback [1/s]
};

/// (q, v, tau, external forces) => data.ddq and data.lambda (and data.M, data.L, data.J,
/// data.residual when beta != 0). Without loops this is CRBA + Cholesky forward dynamics.
const Eigen::VectorXd& constrainedForwardDynamics(const Model& model, Data& data, const Eigen::VectorXd& q,
                                                  const Eigen::VectorXd& v, const Eigen::VectorXd& tau,
                                                  const ExternalForces* fext = nullptr, const Baumgarte& stab = {});

}  // namespace yardsim::dynamics
