#include "forces/hydro/source_distribution.hpp"

#include <numbers>

#include <Eigen/LU>

#include "forces/hydro/rankine_integrals.hpp"

namespace yardsim::forces::hydro {

SourceDistribution::SourceDistribution(std::vector<Panel> panels, FreeSurface fs, const Eigen::VectorXd& normalVelocity)
    : panels_(std::move(panels)), fs_(fs) {
  // (panels) => B_ij = n_i . grad G_j(x_i) - 2 pi delta_ij, then B sigma = dphi/dn
  const auto n = static_cast<Eigen::Index>(panels_.size());
  Eigen::MatrixXd B(n, n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const Panel& pj = panels_[static_cast<std::size_t>(j)];
    for (Eigen::Index i = 0; i < n; ++i) {
      const Panel& pi = panels_[static_cast<std::size_t>(i)];
      B(i, j) = pi.normal.dot(unitVelocity(pj, pi.centroid));
    }
  }
  B.diagonal().array() -= 2.0 * std::numbers::pi;
  sigma_ = B.partialPivLu().solve(normalVelocity);
}

Vector3 SourceDistribution::unitVelocity(const Panel& p, const Vector3& x) const {
  Vector3 g = sourceGradient(p, x);
  if (fs_ == FreeSurface::NegativeImage) {
    const Vector3 gi = sourceGradient(p, mirrorInWaterPlane(x));
    g -= mirrorInWaterPlane(gi);
  }
  return g;
}

double SourceDistribution::potential(const Vector3& x) const {
  double phi = 0.0;
  for (std::size_t j = 0; j < panels_.size(); ++j) {
    double s = panelIntegrals(panels_[j], x).source;
    if (fs_ == FreeSurface::NegativeImage) s -= panelIntegrals(panels_[j], mirrorInWaterPlane(x)).source;
    phi += sigma_[static_cast<Eigen::Index>(j)] * s;
  }
  return phi;
}

Vector3 SourceDistribution::velocity(const Vector3& x) const {
  Vector3 u = Vector3::Zero();
  for (std::size_t j = 0; j < panels_.size(); ++j) u += sigma_[static_cast<Eigen::Index>(j)] * unitVelocity(panels_[j], x);
  return u;
}

}  // namespace yardsim::forces::hydro
