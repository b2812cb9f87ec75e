#include "forces/hydro/far_field.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "forces/airy_waves.hpp"

namespace yardsim::forces::hydro {

double groupVelocity(double omega, double depth, double g) {
  // (dispersion w^2 = g k tanh kh) => c_g = w / (2k) (1 + 2kh / sinh 2kh); deep: g / (2w)
  const double k = forces::waveNumber(omega, depth, g);
  if (!std::isfinite(depth) || 2.0 * k * depth > 700.0) return 0.5 * omega / k;
  return 0.5 * omega / k * (1.0 + 2.0 * k * depth / std::sinh(2.0 * k * depth));
}

double radiatedPower(const RankineTdModel& model, const Eigen::VectorXcd& surfaceAmplitude,
                     double omega, double rInner, double rOuter) {
  const std::vector<Panel>& panels = model.problem().surface();
  if (surfaceAmplitude.size() != static_cast<Eigen::Index>(panels.size()) || !(rOuter > rInner))
    throw std::invalid_argument(
        "radiatedPower: one amplitude per free-surface panel and rOuter > rInner");
  // (panels with centroids in the annulus) => int |zeta|^2 dA / (rOuter - rInner)
  //   = the annulus mean of int |zeta|^2 r dtheta
  const Vector3& c = model.freeSurface().centre;
  double sum = 0.0, area = 0.0;
  for (std::size_t i = 0; i < panels.size(); ++i) {
    const double r = (panels[i].centroid - c).head<2>().norm();
    if (r < rInner || r > rOuter) continue;
    sum += std::norm(surfaceAmplitude[static_cast<Eigen::Index>(i)]) * panels[i].area;
    area += panels[i].area;
  }
  if (area <= 0.0)
    throw std::invalid_argument("radiatedPower: no free-surface panel in the annulus");
  const RankineTdSettings& s = model.settings();
  // (the panels cover the annulus only approximately) => scale by the annulus' exact area
  const double ring = std::numbers::pi * (rOuter * rOuter - rInner * rInner);
  const double lineIntegral = sum / area * ring / (rOuter - rInner);
  return 0.5 * s.rho * s.g * groupVelocity(omega, s.depth, s.g) * lineIntegral;
}

}  // namespace yardsim::forces::hydro
