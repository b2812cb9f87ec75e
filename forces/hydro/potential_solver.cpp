#include "forces/hydro/potential_solver.hpp"

#include <numbers>
#include <string>

#include <unsupported/Eigen/IterativeSolvers>

namespace yardsim::forces::hydro {

PotentialSolver::PotentialSolver(std::vector<Panel> panels, const SolverOptions& options)
    : PotentialSolver(panels, options, assembleInfluence(panels, options.freeSurface)) {}

PotentialSolver::PotentialSolver(std::vector<Panel> panels, const SolverOptions& options, InfluenceMatrices&& influence)
    : panels_(std::move(panels)),
      options_(options),
      source_(std::move(influence.source)),
      system_(std::move(influence.dipole)) {
  // (D) => K = 2 pi I - D in place, then its LU factors in place
  system_ *= -1.0;
  system_.diagonal().array() += 2.0 * std::numbers::pi;
  if (options_.linearSolver == LinearSolver::DenseLU) lu_.emplace(system_);
}

Eigen::MatrixXd PotentialSolver::solve(const Eigen::MatrixXd& normalVelocity) const {
  // (dphi/dn) => right-hand side -S dphi/dn, then K phi = rhs
  return solveSystem(-(source_ * normalVelocity));
}

Eigen::MatrixXd PotentialSolver::solveSystem(const Eigen::MatrixXd& rhs) const {
  if (options_.linearSolver == LinearSolver::DenseLU) {
    lastIterations_ = 0;
    return lu_->solve(rhs);
  }
  // (K, rhs) => phi column by column by restarted GMRES
  Eigen::GMRES<Eigen::MatrixXd, Eigen::IdentityPreconditioner> gmres;
  gmres.setTolerance(options_.gmresTolerance);
  gmres.setMaxIterations(options_.gmresMaxIterations);
  gmres.set_restart(options_.gmresRestart);
  gmres.compute(system_);
  Eigen::MatrixXd phi(rhs.rows(), rhs.cols());
  for (Eigen::Index c = 0; c < rhs.cols(); ++c) {
    phi.col(c) = gmres.solve(rhs.col(c));
    lastIterations_ = static_cast<int>(gmres.iterations());
    if (gmres.info() != Eigen::Success) {
      throw SolverError("GMRES did not converge on " + std::to_string(panels_.size()) + " panels: residual " +
                        std::to_string(gmres.error()) + " after " + std::to_string(gmres.iterations()) +
                        " iterations (tolerance " + std::to_string(options_.gmresTolerance) +
                        "); check the mesh (normals into the fluid, no gaps) or use the dense LU");
    }
  }
  return phi;
}

}  // namespace yardsim::forces::hydro
