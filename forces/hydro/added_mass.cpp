#include "forces/hydro/added_mass.hpp"

#include <stdexcept>

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

}  // namespace yardsim::forces::hydro
