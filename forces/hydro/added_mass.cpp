#include "forces/hydro/added_mass.hpp"

#include <stdexcept>
#include <string>

#include "forces/hydro/wetted_surface.hpp"

namespace yardsim::forces::hydro {

Eigen::MatrixXd modeNormals(const std::vector<Panel>& panels, const Vector3& reference) {
  // (n, centroid) => [n, (c - x_R) x n] per panel
  Eigen::MatrixXd N(static_cast<Eigen::Index>(panels.size()), 6);
  for (std::size_t k = 0; k < panels.size(); ++k) {
    const Panel& p = panels[k];
    const auto row = static_cast<Eigen::Index>(k);
    N.block<1, 3>(row, 0) = p.normal.transpose();
    N.block<1, 3>(row, 3) = (p.centroid - reference).cross(p.normal).transpose();
  }
  return N;
}

Matrix6 addedMass(const PotentialSolver& solver, const Vector3& reference, double rho) {
  if (!(rho > 0.0)) throw std::invalid_argument("added mass: fluid density must be > 0");
  // (N) => phi_j, then A = -rho N^T diag(area) phi
  const Eigen::MatrixXd N = modeNormals(solver.panels(), reference);
  const Eigen::MatrixXd phi = solver.solve(N);
  Eigen::VectorXd area(N.rows());
  for (std::size_t k = 0; k < solver.panels().size(); ++k) area[static_cast<Eigen::Index>(k)] = solver.panels()[k].area;
  return -rho * (N.transpose() * area.asDiagonal() * phi);
}

Matrix6 addedMass(const PanelMesh& wetted, const AddedMassOptions& options) {
  const PotentialSolver solver(buildPanels(wetted), options.solver);
  return addedMass(solver, options.reference, options.rho);
}

Matrix6 floatingAddedMass(const PanelMesh& hull_B, const dynamics::Transform& X_WB, double rho, double waterLevel,
                          LinearSolver linearSolver) {
  // (hull in B, X_WB) => hull in world axes with z measured from the water level, then its part
  // below the mean water plane
  const Vector3 level(0.0, 0.0, waterLevel);
  PanelMesh hull_W = hull_B;
  for (Vector3& v : hull_W.vertices) v = X_WB.actPoint(v) - level;
  const PanelMesh wet = wettedSurface(hull_W);
  if (wet.panelCount() == 0)
    throw PanelError("the hull is dry at its mean position (nothing below the water level z = " + std::to_string(waterLevel) + " m)");
  // (wetted surface) => A about the body origin in world axes, then in body axes: R^T A_blk R
  AddedMassOptions o;
  o.rho = rho;
  o.reference = X_WB.p - level;
  o.solver.freeSurface = FreeSurface::NegativeImage;
  o.solver.linearSolver = linearSolver;
  const Matrix6 A_W = addedMass(wet, o);
  Matrix6 R = Matrix6::Zero();
  R.topLeftCorner<3, 3>() = X_WB.R;
  R.bottomRightCorner<3, 3>() = X_WB.R;
  return R.transpose() * A_W * R;
}

}  // namespace yardsim::forces::hydro
