#include "forces/hydro/td_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "forces/hydro/panel_geometry.hpp"
#include "forces/hydro/wetted_surface.hpp"

namespace yardsim::forces::hydro {

namespace {

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", x);
  return buf;
}

}  // namespace

std::optional<std::string> checkTruncation(const PanelMesh& hull_W, const FreeSurfaceSettings& s) {
  // (wetted hull) => waterline centre, then the farthest hull vertex horizontally
  const PanelMesh wet = wettedSurface(hull_W);
  if (wet.panelCount() == 0) return "the hull is dry at its mean position";
  const std::vector<int> loop = waterlineLoop(wet);
  Vector3 c = Vector3::Zero();
  for (const int v : loop)
    c += wet.vertices[static_cast<std::size_t>(v)] / static_cast<double>(loop.size());
  double reach = 0.0;
  for (const Vector3& v : hull_W.vertices)
    reach = std::max(reach, std::hypot(v.x() - c.x(), v.y() - c.y()));
  const double inner = s.truncationRadius - s.dampingWidth;
  if (reach >= inner) {
    return "the hull reaches " + number(reach) +
           " m from its waterline centre, beyond the free surface's undamped part (truncation "
           "radius " +
           number(s.truncationRadius) + " m - damping zone " + number(s.dampingWidth) +
           " m = " + number(inner) + " m)";
  }
  return std::nullopt;
}

std::optional<std::string> checkPanelSize(const FreeSurfaceMesh& surface,
                                          const FreeSurfaceSettings& s, double shortestPeriod,
                                          double g) {
  const double shortest = g * shortestPeriod * shortestPeriod / (2.0 * std::numbers::pi);
  const double inner = s.truncationRadius - s.dampingWidth;
  double largest = 0.0;
  for (const Panel& p : buildPanels(surface.mesh)) {
    if ((p.centroid - surface.centre).head<2>().norm() < inner)
      largest = std::max(largest, p.diameter);
  }
  if (largest > 0.1 * shortest) {
    return "a free-surface panel is " + number(largest) +
           " m across, more than a tenth of the shortest wave (" + number(shortest) +
           " m at T = " + number(shortestPeriod) +
           " s): refine the free surface (maxSpacing, or more waterline vertices) or drop the "
           "short waves";
  }
  return std::nullopt;
}

std::optional<std::string> checkEmpStep(const EmpLimit& limit, double dt) {
  if (dt > limit.dtMax) {
    return "the step " + number(dt) + " s is above the emp limit " + number(limit.dtMax) +
           " s of the free-surface mesh (g lambda_max dt^2 <= 4, lambda_max " +
           number(limit.lambdaMax) + " 1/m, smallest panel " + number(limit.smallestPanel) + " m)";
  }
  return std::nullopt;
}

std::optional<std::string> checkSurfaceGrowth(const SurfaceGrowth& growth, double nu0,
                                              double until) {
  if (!(growth.rate * until > kSurfaceGrowthLimit)) return std::nullopt;
  // (undamped rate) => a uniform damping 10 % above it (the growth then stops, with a margin)
  const double undamped = growth.rate + nu0;
  return "the free surface's short waves of the mesh grow at " + number(growth.rate) + " 1/s (at " +
         number(growth.frequency) + " rad/s" +
         (nu0 > 0 ? ", surface_damping " + number(nu0) + " 1/s included" : std::string()) +
         "), by a factor " + number(std::exp(growth.rate * until)) + " over " + number(until) +
         " s (at most e^" + number(kSurfaceGrowthLimit) +
         "): set settings.surface_damping to at least " + number(1.1 * undamped) +
         " 1/s (a uniform damping in the beach's form: the real frequencies kept), or end the run "
         "before " +
         number(kSurfaceGrowthLimit / growth.rate) + " s";
}

}  // namespace yardsim::forces::hydro
