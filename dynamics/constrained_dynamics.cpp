#include "dynamics/constrained_dynamics.hpp"

#include "dynamics/crba.hpp"
#include "dynamics/loop_constraints.hpp"
#include "dynamics/rnea.hpp"
#include "dynamics/semidefinite_solve.hpp"
#include "dynamics/tree_cholesky.hpp"

namespace yardsim::dynamics {

const Eigen::VectorXd& constrainedForwardDynamics(const Model& m, Data& d, const Eigen::VectorXd& q,
                                                  const Eigen::VectorXd& v, const Eigen::VectorXd& tau,
                                                  const ExternalForces* fext, const Baumgarte& stab) {
  // (q, v, tau) => M = L L^T, h, ddq_free = M^-1 (tau - h)
  crba(m, d, q);
  choleskyFactor(m, d);
  biasForces(m, d, q, v, fext);
  d.ddq = tau - d.nle;
  choleskySolveInPlace(m, d, d.ddq);
  if (m.nc == 0) return d.ddq;
  // (q, v) => J, J v, kappa, residual
  if (stab.beta != 0.0) loopResidual(m, d, q);
  loopJacobianAndBias(m, d, q, v);
  // (J, L) => M^-1 J^T, Schur complement J M^-1 J^T
  d.MinvJt = d.J.transpose();
  choleskySolveInPlace(m, d, d.MinvJt);
  d.schur.noalias() = d.J * d.MinvJt;
  // (Schur, rhs) => lambda; ddq += M^-1 J^T lambda
  d.rhs = -d.kappa - 2.0 * stab.alpha * d.cv;
  if (stab.beta != 0.0) d.rhs -= stab.beta * stab.beta * d.residual;
  d.rhs.noalias() -= d.J * d.ddq;
  d.lambda = d.rhs;
  d.schurRank = semidefiniteSolve(d.schur, d.lambda, d.perm, d.work);
  d.ddq.noalias() += d.MinvJt * d.lambda;
  return d.ddq;
}

}  // namespace yardsim::dynamics
