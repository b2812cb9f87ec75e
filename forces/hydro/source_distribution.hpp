#pragma once
// Source strengths, only where field velocities are needed (the added mass and the pressures come
// from the potential formulation, potential_solver.hpp). A constant source density sigma_j on
// each panel, with the same Green function and image as the potential solver:
//   phi(x) = sum_j sigma_j (S_j(x) - S_j(x')),  grad phi(x) = sum_j sigma_j (grad S_j(x) - M grad S_j(x'))
// (M = diag(1, 1, -1) the mirror in z = 0), the strengths from the normal velocity at the
// collocation points (n out of the body, the fluid side's jump -2 pi sigma_i):
//   -2 pi sigma_i + sum_j sigma_j n_i . (grad S_j(x_i) - M grad S_j(x_i')) = dphi/dn_i
// solved once by a dense LU. First order in the panel size on the body (the potential
// formulation is second order), accurate away from it.
#include <vector>

#include <Eigen/Core>

#include "forces/hydro/influence_matrices.hpp"

namespace yardsim::forces::hydro {

class SourceDistribution {
 public:
  /// (panels, free surface, dphi/dn per panel) => the source strengths.
  SourceDistribution(std::vector<Panel> panels, FreeSurface fs, const Eigen::VectorXd& normalVelocity);

  const Eigen::VectorXd& strengths() const { return sigma_; }
  /// (x in the fluid) => phi(x)
  double potential(const Vector3& x) const;
  /// (x in the fluid) => grad phi(x), the fluid velocity
  Vector3 velocity(const Vector3& x) const;

 private:
  // (panel j, x) => grad of (S_j(x) - S_j(x')) (no image term without a free surface)
  Vector3 unitVelocity(const Panel& p, const Vector3& x) const;

  std::vector<Panel> panels_;
  FreeSurface fs_;
  Eigen::VectorXd sigma_;
};

}  // namespace yardsim::forces::hydro
