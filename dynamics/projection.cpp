#include "dynamics/projection.hpp"

#include "dynamics/configuration.hpp"
#include "dynamics/crba.hpp"
#include "dynamics/loop_constraints.hpp"
#include "dynamics/semidefinite_solve.hpp"
#include "dynamics/tree_cholesky.hpp"

namespace yardsim::dynamics {

namespace {
// (q, J) => M^-1 J^T and the Schur complement J M^-1 J^T
void schurComplement(const Model& m, Data& d, const Eigen::VectorXd& q) {
  crba(m, d, q);
  choleskyFactor(m, d);
  d.MinvJt = d.J.transpose();
  choleskySolveInPlace(m, d, d.MinvJt);
  d.schur.noalias() = d.J * d.MinvJt;
}
}  // namespace

double projectPositions(const Model& m, Data& d, Eigen::VectorXd& q, double tol, int maxIterations) {
  if (m.nc == 0) return 0.0;
  double err = loopResidualNorm(m, d, q);
  for (int it = 0; it < maxIterations && err > tol; ++it) {
    // (q, g) => dq = -M^-1 J^T (J M^-1 J^T)^+ g; q = q (+) dq
    loopJacobian(m, d, q);
    schurComplement(m, d, q);
    d.lambda = d.residual;
    d.schurRank = semidefiniteSolve(d.schur, d.lambda, d.perm, d.work);
    d.dv.noalias() = -d.MinvJt * d.lambda;
    integrate(m, q, d.dv, 1.0, q);
    err = loopResidualNorm(m, d, q);
  }
  return err;
}

double projectVelocities(const Model& m, Data& d, const Eigen::VectorXd& q, Eigen::VectorXd& v) {
  if (m.nc == 0) return 0.0;
  // (q, v) => v -= M^-1 J^T (J M^-1 J^T)^+ J v
  loopJacobian(m, d, q);
  schurComplement(m, d, q);
  d.lambda.noalias() = d.J * v;
  d.schurRank = semidefiniteSolve(d.schur, d.lambda, d.perm, d.work);
  v.noalias() -= d.MinvJt * d.lambda;
  d.cv.noalias() = d.J * v;
  return d.cv.cwiseAbs().maxCoeff();
}

}  // namespace yardsim::dynamics
