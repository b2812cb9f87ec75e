#pragma once
// The fixed part of the time-domain Rankine-panel solution for one floating hull, linear about
// its mean wetted surface, zero forward speed: the free-surface panels and their damping, the
// mixed boundary-value problem factorised once (mixed_problem.hpp), the generalised normals and
// the impulsive decomposition
//   phi = sum_j psi_j xi_dot_j + phi^M,  psi_j = 0 on z = 0, dpsi_j/dn = N_j on the hull,
// from which the infinite-frequency added mass A_inf = -rho int psi_j N_i dS (the same
// factorisation) and the maps from the data of the dphi^M/dt problem (Dirichlet -g zeta on the
// free surface, a Neumann value on the hull) to the hull force, F^M = -rho int dphi^M/dt N dS.
//
// Frames and units: everything here is in world axes W at the mean pose, z up, the still-water
// level z = waterLevel moved to z = 0, moments about the body origin (X_WB.p); rows and columns
// surge, sway, heave, roll, pitch, yaw. Force N, moment N m, lengths m, rho kg/m^3, g m/s^2.
#include <limits>
#include <memory>

#include <Eigen/Core>

#include "dynamics/spatial.hpp"
#include "forces/hydro/free_surface_mesh.hpp"
#include "forces/hydro/mixed_problem.hpp"

namespace yardsim::forces::hydro {

struct RankineTdSettings {
  FreeSurfaceSettings freeSurface;
  double rho = 1025.0;  ///< kg/m^3
  double g = 9.80665;   ///< m/s^2
  double depth =
      std::numeric_limits<double>::infinity();  ///< m below the still-water level (sea-bed image)
  double waterLevel = 0.0;                      ///< z of the still-water level in W, m
};

class RankineTdModel {
 public:
  using Matrix6 = Eigen::Matrix<double, 6, 6>;

  /// (hull in B, mean pose X_WB, settings) => the panels, the factorised problem, A_inf and the
  /// force maps. Throws PanelError (bad or dry hull) or FreeSurfaceError (free surface).
  RankineTdModel(const PanelMesh& hull_B, const dynamics::Transform& X_WB,
                 const RankineTdSettings& settings);

  const RankineTdSettings& settings() const { return settings_; }
  const MixedProblem& problem() const { return *problem_; }
  const FreeSurfaceMesh& freeSurface() const { return surface_; }
  /// nu per free-surface panel, 1/s
  const Eigen::VectorXd& damping() const { return damping_; }
  /// Nb x 6 generalised normals N = [n; (x - x_O) x n] at the hull centroids, x_O the body origin
  const Eigen::MatrixXd& modes() const { return modes_; }
  /// Infinite-frequency added mass from psi_j (W axes, about the body origin)
  const Matrix6& aInf() const { return aInf_; }
  /// F^M = forceFromBody a + forceFromSurface p for the dphi^M/dt problem with Neumann a (Nb,
  /// m/s^2) on the hull and Dirichlet p (Nf, m^2/s^2) on the free surface; 6 x Nb and 6 x Nf
  const Eigen::MatrixXd& forceFromBody() const { return forceFromBody_; }
  const Eigen::MatrixXd& forceFromSurface() const { return forceFromSurface_; }
  /// body origin in the solver's frame (W shifted by the water level), m
  const Vector3& origin() const { return origin_; }
  /// rotation R_WB of the mean pose (to turn 6x6 results into body axes: R^T M R blockwise)
  const Eigen::Matrix3d& rotation() const { return R_WB_; }
  /// Time and set-up: assembly and LU seconds are in problem(); this is the adjoint solve and maps
  double mapSeconds() const { return mapSeconds_; }

 private:
  RankineTdSettings settings_;
  FreeSurfaceMesh surface_;
  std::unique_ptr<MixedProblem> problem_;
  Eigen::VectorXd damping_;
  Eigen::MatrixXd modes_;
  Matrix6 aInf_;
  Eigen::MatrixXd forceFromBody_, forceFromSurface_;
  Vector3 origin_;
  Eigen::Matrix3d R_WB_;
  double mapSeconds_ = 0.0;
};

/// (6x6 in W axes, R_WB) => the same in body axes: R^T M R on each 3x3 block.
Eigen::Matrix<double, 6, 6> toBodyAxes(const Eigen::Matrix<double, 6, 6>& M_W,
                                       const Eigen::Matrix3d& R_WB);

}  // namespace yardsim::forces::hydro
