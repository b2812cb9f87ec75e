#pragma once
// The potential formulation (Green's second identity) on the body surface, with n out of the
// body into the fluid and G the Green function of influence_matrices.hpp:
//   2 pi phi(x_i) - sum_j D_ij phi_j = - sum_j S_ij (dphi/dn)_j
// for the potential phi at the collocation points given the normal velocity dphi/dn on each
// panel (constant per panel). The system matrix K = 2 pi I - D is made once per geometry and
// solved either by a dense partial-pivot LU (factorised once, then one back-substitution per
// right-hand side) or by restarted GMRES (no factorisation: O(N^2) per iteration, for panel counts
// where the O(N^3) LU costs too much). K is a second-kind operator: GMRES converges in a number
// of iterations that hardly grows with N.
#include <optional>
#include <stdexcept>
#include <vector>

#include <Eigen/Core>
#include <Eigen/LU>

#include "forces/hydro/influence_matrices.hpp"

namespace yardsim::forces::hydro {

enum class LinearSolver {
  DenseLU,  ///< Eigen partial-pivot LU, once per geometry
  Gmres     ///< restarted GMRES, per right-hand side
};

struct SolverOptions {
  FreeSurface freeSurface = FreeSurface::None;
  LinearSolver linearSolver = LinearSolver::DenseLU;
  double gmresTolerance = 1e-10;  ///< relative residual
  int gmresMaxIterations = 500;
  int gmresRestart = 60;
};

/// GMRES did not reach its tolerance.
class SolverError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class PotentialSolver {
 public:
  /// (panels, options) => S and K assembled (and K factorised for DenseLU).
  PotentialSolver(std::vector<Panel> panels, const SolverOptions& options);
  /// (panels, options, S and D already assembled) => the same without assembling again.
  PotentialSolver(std::vector<Panel> panels, const SolverOptions& options, InfluenceMatrices&& influence);
  /// Not copyable or movable: the LU factors refer to the matrix they overwrite.
  PotentialSolver(const PotentialSolver&) = delete;
  PotentialSolver& operator=(const PotentialSolver&) = delete;

  /// (dphi/dn, N x m: one column per case) => phi at the collocation points, N x m. Throws
  /// SolverError when GMRES does not converge.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& normalVelocity) const;
  /// (b, N x m) => phi with K phi = b: the LU's back-substitution, or GMRES column by column.
  Eigen::MatrixXd solveSystem(const Eigen::MatrixXd& b) const;

  const std::vector<Panel>& panels() const { return panels_; }
  const SolverOptions& options() const { return options_; }
  /// GMRES iterations of the last solved column (0 for the LU).
  int lastIterations() const { return lastIterations_; }

 private:
  std::vector<Panel> panels_;
  SolverOptions options_;
  Eigen::MatrixXd source_;  ///< S
  Eigen::MatrixXd system_;  ///< K = 2 pi I - D; overwritten by its LU factors for DenseLU
  std::optional<Eigen::PartialPivLU<Eigen::Ref<Eigen::MatrixXd>>> lu_;
  mutable int lastIterations_ = 0;
};

}  // namespace yardsim::forces::hydro
