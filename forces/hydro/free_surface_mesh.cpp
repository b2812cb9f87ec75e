#include "forces/hydro/free_surface_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <string>

namespace yardsim::forces::hydro {

FreeSurfaceSettings defaultBeach(FreeSurfaceSettings s, double longestPeriod, double g) {
  // (T) => width lambda = g T^2 / (2 pi), nu_max = 2 pi / T
  s.dampingWidth = g * longestPeriod * longestPeriod / (2.0 * std::numbers::pi);
  s.dampingStrength = 2.0 * std::numbers::pi / longestPeriod;
  return s;
}

std::vector<int> waterlineLoop(const PanelMesh& wetted) {
  // (panels) => directed edges; an edge whose reverse is absent is open
  double size = 0.0;
  for (const Vector3& v : wetted.vertices) size = std::max(size, v.norm());
  const double tol = 1e-9 * std::max(size, 1.0);
  std::set<std::pair<int, int>> edges;
  for (const auto& ix : wetted.panels) {
    const int n = ix[3] < 0 ? 3 : 4;
    for (int j = 0; j < n; ++j)
      edges.emplace(ix[static_cast<std::size_t>(j)], ix[static_cast<std::size_t>((j + 1) % n)]);
  }
  std::map<int, int> next;
  for (const auto& [a, b] : edges) {
    const bool onPlane = std::abs(wetted.vertices[static_cast<std::size_t>(a)].z()) <= tol &&
                         std::abs(wetted.vertices[static_cast<std::size_t>(b)].z()) <= tol;
    if (onPlane && !edges.contains({b, a})) {
      if (!next.emplace(a, b).second)
        throw FreeSurfaceError("waterline: vertex " + std::to_string(a) + " starts two open edges");
    }
  }
  if (next.size() < 3)
    throw FreeSurfaceError(
        "waterline: the wetted hull has no closed waterline on z = 0 (fewer than 3 open edges "
        "there)");
  // (next) => one loop from the first vertex; every open edge must be on it
  std::vector<int> loop{next.begin()->first};
  while (true) {
    const auto it = next.find(loop.back());
    if (it == next.end())
      throw FreeSurfaceError("waterline: open at vertex " + std::to_string(loop.back()));
    if (it->second == loop.front()) break;
    loop.push_back(it->second);
    if (loop.size() > next.size())
      throw FreeSurfaceError("waterline: the open edges do not close into a loop");
  }
  if (loop.size() != next.size()) {
    throw FreeSurfaceError("waterline: " + std::to_string(next.size()) +
                           " open edges on z = 0 but the loop has " + std::to_string(loop.size()) +
                           " (several waterlines: one floating hull per solver)");
  }
  // (loop) => counter-clockwise seen from above (positive signed area)
  double area = 0.0;
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const Vector3& a = wetted.vertices[static_cast<std::size_t>(loop[k])];
    const Vector3& b = wetted.vertices[static_cast<std::size_t>(loop[(k + 1) % loop.size()])];
    area += a.x() * b.y() - b.x() * a.y();
  }
  if (area < 0.0) std::reverse(loop.begin(), loop.end());
  return loop;
}

namespace {

// (settings, mean and least waterline radius) => ring distances d_0 = 0 < d_1 < ... = R - r_mean;
// the beach spacing from where the ray of the least radius enters the zone (every ray has)
std::vector<double> ringDistances(const FreeSurfaceSettings& s, double rMean, double rMin) {
  const double span = s.truncationRadius - rMean;
  const double zone =
      (s.truncationRadius - s.dampingWidth - rMin) * span / (s.truncationRadius - rMin);
  const double beach = s.beachSpacing > 0.0 ? s.beachSpacing : s.maxSpacing;
  std::vector<double> d{0.0};
  double h = s.firstSpacing;
  while (d.back() + 0.5 * h < span) {
    if (d.size() > static_cast<std::size_t>(kMaxFreeSurfacePanels))
      throw FreeSurfaceError("free surface: more than " + std::to_string(kMaxFreeSurfacePanels) +
                             " rings of " + std::to_string(h) + " m out to " +
                             std::to_string(s.truncationRadius) +
                             " m (the dense solver's limit): raise maxSpacing");
    d.push_back(d.back() + h);
    h = std::min(h * s.growth, d.back() < zone ? s.maxSpacing : beach);
  }
  // (rings) => stretched so that the last one lands on the truncation radius
  const double scale = span / d.back();
  for (double& x : d) x *= scale;
  return d;
}

// (edge length, limit) => the fewest equal parts 2^j with length / 2^j <= limit (1: no limit)
int splitsFor(double length, double limit) {
  int n = 1;
  if (limit > 0.0)
    while (length > n * limit && n < (1 << 20)) n *= 2;
  return n;
}

}  // namespace

FreeSurfaceMesh buildFreeSurface(const PanelMesh& wetted, const FreeSurfaceSettings& s) {
  if (!(s.firstSpacing > 0.0) || !(s.maxSpacing >= s.firstSpacing) || !(s.growth >= 1.0) ||
      !(s.dampingWidth >= 0.0) || !(s.dampingStrength >= 0.0) || !(s.surfaceDamping >= 0.0)) {
    throw FreeSurfaceError(
        "free surface: need firstSpacing > 0, maxSpacing >= firstSpacing, growth >= 1, "
        "dampingWidth, dampingStrength and surfaceDamping >= 0");
  }
  const std::vector<int> loop = waterlineLoop(wetted);
  const auto nw = static_cast<int>(loop.size());
  FreeSurfaceMesh out;
  // (loop) => centre c, polar coordinates (r_k, theta_k) of the waterline vertices
  for (const int v : loop) out.centre += wetted.vertices[static_cast<std::size_t>(v)];
  out.centre /= nw;
  out.centre.z() = 0.0;
  std::vector<double> r(static_cast<std::size_t>(nw)), theta(static_cast<std::size_t>(nw));
  double rMean = 0.0;
  for (int k = 0; k < nw; ++k) {
    const Vector3 d =
        wetted.vertices[static_cast<std::size_t>(loop[static_cast<std::size_t>(k)])] - out.centre;
    r[static_cast<std::size_t>(k)] = std::hypot(d.x(), d.y());
    theta[static_cast<std::size_t>(k)] = std::atan2(d.y(), d.x());
    rMean += r[static_cast<std::size_t>(k)] / nw;
    out.waterlineRadius = std::max(out.waterlineRadius, r[static_cast<std::size_t>(k)]);
  }
  // (theta) => star-shaped: the azimuth turns once round, always forward
  double turn = 0.0;
  for (int k = 0; k < nw; ++k) {
    double dt = theta[static_cast<std::size_t>((k + 1) % nw)] - theta[static_cast<std::size_t>(k)];
    dt = std::remainder(dt, 2.0 * std::numbers::pi);
    if (!(dt > 0.0)) {
      throw FreeSurfaceError("free surface: the waterline is not star-shaped about its centre (" +
                             std::to_string(out.centre.x()) + ", " +
                             std::to_string(out.centre.y()) +
                             ") m: its azimuth turns back at waterline vertex " +
                             std::to_string(loop[static_cast<std::size_t>(k)]));
    }
    turn += dt;
  }
  if (std::abs(turn - 2.0 * std::numbers::pi) > 1e-6)
    throw FreeSurfaceError("free surface: the waterline does not go once round its centre");
  if (!(s.truncationRadius > out.waterlineRadius + s.firstSpacing)) {
    throw FreeSurfaceError(
        "free surface: the hull reaches the truncation radius: waterline radius " +
        std::to_string(out.waterlineRadius) + " m + first ring " + std::to_string(s.firstSpacing) +
        " m >= truncationRadius " + std::to_string(s.truncationRadius) + " m");
  }
  if (s.dampingWidth >= s.truncationRadius - out.waterlineRadius) {
    throw FreeSurfaceError("free surface: the damping zone (" + std::to_string(s.dampingWidth) +
                           " m wide) reaches the hull (waterline radius " +
                           std::to_string(out.waterlineRadius) + " m, truncation radius " +
                           std::to_string(s.truncationRadius) + " m)");
  }
  // (rings) => ray points: ring 0 on the waterline, ring m at r_k + t_m (R - r_k) along theta_k
  const std::vector<double> d = ringDistances(s, rMean, *std::min_element(r.begin(), r.end()));
  const double span = s.truncationRadius - rMean;
  const auto rings = static_cast<int>(d.size());
  std::vector<Vector3> ray(d.size() * static_cast<std::size_t>(nw));
  for (int m = 0; m < rings; ++m) {
    for (int k = 0; k < nw; ++k) {
      const auto sk = static_cast<std::size_t>(k);
      const double rr =
          r[sk] + d[static_cast<std::size_t>(m)] / span * (s.truncationRadius - r[sk]);
      ray[static_cast<std::size_t>(m * nw + k)] =
          m == 0 ? wetted.vertices[static_cast<std::size_t>(loop[sk])]
                 : Vector3(out.centre +
                           Vector3(rr * std::cos(theta[sk]), rr * std::sin(theta[sk]), 0.0));
    }
  }
  const auto at = [&](int m, int k) -> const Vector3& {
    return ray[static_cast<std::size_t>(m * nw + (k % nw))];
  };
  // (rows m between rings m, m + 1) => splits n(m, k): edges along the rings <= the row's limit
  const double zoneStart = s.truncationRadius - s.dampingWidth;
  const double beach = s.beachSpacing > 0.0 ? s.beachSpacing : s.azimuthSpacing;
  std::vector<int> split(static_cast<std::size_t>((rings - 1) * nw), 1);
  if (s.azimuthSpacing > 0.0) {
    for (int m = 0; m + 1 < rings; ++m) {
      for (int k = 0; k < nw; ++k) {
        // (the row's corners) => in the zone when none lies inside its inner edge
        bool inZone = true;
        for (const Vector3& v : {at(m, k), at(m, k + 1)})
          inZone =
              inZone && std::hypot(v.x() - out.centre.x(), v.y() - out.centre.y()) >= zoneStart;
        const double edge =
            std::max((at(m, k + 1) - at(m, k)).norm(), (at(m + 1, k + 1) - at(m + 1, k)).norm());
        split[static_cast<std::size_t>(m * nw + k)] =
            splitsFor(edge, inZone ? beach : s.azimuthSpacing);
      }
    }
  }
  // (splits) => the panel count against the dense solver's limit, before anything is made
  long long panels = 0;
  for (const int n : split) panels += n;
  if (panels > kMaxFreeSurfacePanels)
    throw FreeSurfaceError("free surface: " + std::to_string(panels) + " panels, more than " +
                           std::to_string(kMaxFreeSurfacePanels) +
                           " (the dense solver's limit: its matrices take 3 N^2 doubles): raise "
                           "maxSpacing or azimuthSpacing");
  // (splits) => vertices: ring m, ray k, then the points towards ray k + 1 at the finer of the
  // two rows' splits (a ray's point first: unsplit, the rings' vertices in ray order)
  std::vector<int> level(d.size() * static_cast<std::size_t>(nw), 1), first(level.size(), 0);
  for (int m = 0; m < rings; ++m) {
    for (int k = 0; k < nw; ++k) {
      const auto rowSplit = [&](int row) { return split[static_cast<std::size_t>(row * nw + k)]; };
      const int n = std::max(m > 0 ? rowSplit(m - 1) : 1, m + 1 < rings ? rowSplit(m) : 1);
      const auto ik = static_cast<std::size_t>(m * nw + k);
      level[ik] = n;
      first[ik] = static_cast<int>(out.mesh.vertices.size());
      for (int j = 0; j < n; ++j)
        out.mesh.vertices.push_back(at(m, k) + (at(m, k + 1) - at(m, k)) * (double(j) / n));
    }
  }
  // (ring m, ray k, part j of n) => the vertex index (j = n: ray k + 1's point)
  const auto vertex = [&](int m, int k, int j, int n) {
    if (j == n) return first[static_cast<std::size_t>(m * nw + (k + 1) % nw)];
    const auto ik = static_cast<std::size_t>(m * nw + k);
    return first[ik] + j * (level[ik] / n);
  };
  // (rows m, parts j) => quads with normal -z: (m,j) (m,j+1) (m+1,j+1) (m+1,j) turns clockwise
  // seen from above (k counter-clockwise), i.e. counter-clockwise seen from the fluid below
  for (int m = 0; m + 1 < rings; ++m) {
    for (int k = 0; k < nw; ++k) {
      const int n = split[static_cast<std::size_t>(m * nw + k)];
      for (int j = 0; j < n; ++j) {
        const int a = vertex(m, k, j, n), a1 = vertex(m, k, j + 1, n);
        const int b = vertex(m + 1, k, j, n), b1 = vertex(m + 1, k, j + 1, n);
        out.mesh.addQuad(a, a1, b1, b);
        Vector3 c = Vector3::Zero();
        for (const int v : {a, b, b1, a1})
          c += out.mesh.vertices[static_cast<std::size_t>(v)] / 4.0;
        const double rc = std::hypot(c.x() - out.centre.x(), c.y() - out.centre.y());
        const double x =
            s.dampingWidth > 0.0 ? std::max(0.0, (rc - zoneStart) / s.dampingWidth) : 0.0;
        out.damping.push_back(s.dampingStrength * x * x + s.surfaceDamping);
      }
    }
  }
  return out;
}

}  // namespace yardsim::forces::hydro
