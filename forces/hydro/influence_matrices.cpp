#include "forces/hydro/influence_matrices.hpp"

#include "forces/hydro/rankine_integrals.hpp"

namespace yardsim::forces::hydro {

InfluenceMatrices assembleInfluence(const std::vector<Panel>& panels, FreeSurface fs) {
  const auto n = static_cast<Eigen::Index>(panels.size());
  InfluenceMatrices m{Eigen::MatrixXd(n, n), Eigen::MatrixXd(n, n)};
  // (panel j, collocation points x_i and their images) => column j of S and D
  for (Eigen::Index j = 0; j < n; ++j) {
    const Panel& pj = panels[static_cast<std::size_t>(j)];
    for (Eigen::Index i = 0; i < n; ++i) {
      const Vector3& x = panels[static_cast<std::size_t>(i)].centroid;
      PanelIntegrals v = panelIntegrals(pj, x);
      if (fs == FreeSurface::NegativeImage) {
        const PanelIntegrals w = panelIntegrals(pj, mirrorInWaterPlane(x));
        v.source -= w.source;
        v.dipole -= w.dipole;
      }
      m.source(i, j) = v.source;
      m.dipole(i, j) = v.dipole;
    }
  }
  return m;
}

}  // namespace yardsim::forces::hydro
