#pragma once
// The 6x6 added-mass matrix of a body from the potential formulation: for each mode j (surge,
// sway, heave, roll, pitch, yaw) the radiation potential phi_j with dphi_j/dn = N_j, the
// generalised normal N = [n; (x - x_R) x n] about the reference point x_R (n out of the body),
// then
//   A_ij = -rho int phi_j N_i dS = -rho sum_k phi_j(x_k) N_i(x_k) A_k.
// Rows and columns are ordered surge, sway, heave, roll, pitch, yaw (translations first, the
// naval-architecture and WAMIT order), in the frame of the mesh, about x_R. With
// FreeSurface::NegativeImage this is the infinite-frequency added mass of a floating body (its
// wetted surface in z <= 0); with FreeSurface::None that of a body in unbounded fluid.
#include <Eigen/Core>

#include "dynamics/spatial.hpp"
#include "forces/hydro/potential_solver.hpp"

namespace yardsim::forces::hydro {

using Matrix6 = Eigen::Matrix<double, 6, 6>;

/// (panels, x_R) => N x 6 generalised normals at the collocation points.
Eigen::MatrixXd modeNormals(const std::vector<Panel>& panels, const Vector3& reference);

/// (solver, x_R, rho) => the 6x6 added mass (solves the six radiation problems).
Matrix6 addedMass(const PotentialSolver& solver, const Vector3& reference, double rho);

struct AddedMassOptions {
  double rho = 1025.0;                    ///< kg/m^3
  Vector3 reference = Vector3::Zero();    ///< x_R in the mesh frame
  SolverOptions solver;
};

/// (wetted panel mesh, options) => the 6x6 added mass; throws PanelError for a bad mesh.
Matrix6 addedMass(const PanelMesh& wetted, const AddedMassOptions& options);

/// (hull in the body frame B, its mean pose X_WB, rho, z of the still-water level, linear solver)
/// => the infinite-frequency 6x6 added mass of the floating body: the hull placed in the world,
/// clipped at the mean water plane (wettedSurface), solved with the negative image; returned
/// about the body origin in body axes, naval order. Throws PanelError for a bad mesh or a dry hull.
Matrix6 floatingAddedMass(const PanelMesh& hull_B, const dynamics::Transform& X_WB, double rho, double waterLevel = 0.0,
                          LinearSolver linearSolver = LinearSolver::DenseLU);

}  // namespace yardsim::forces::hydro
