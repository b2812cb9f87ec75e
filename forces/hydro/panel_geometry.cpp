#include "forces/hydro/panel_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>

namespace yardsim::forces::hydro {

namespace {

std::string describe(const PanelMesh& mesh, int k) {
  const auto& ix = mesh.panels[static_cast<std::size_t>(k)];
  std::string s = "panel " + std::to_string(k) + " (vertices " + std::to_string(ix[0]);
  for (int j = 1; j < (ix[3] < 0 ? 3 : 4); ++j) s += ", " + std::to_string(ix[static_cast<std::size_t>(j)]);
  return s + ")";
}

}  // namespace

std::vector<Panel> buildPanels(const PanelMesh& mesh) {
  const int nv = static_cast<int>(mesh.vertices.size());
  std::vector<Panel> out;
  out.reserve(mesh.panels.size());
  std::map<std::pair<int, int>, int> edgeOwner;
  for (int k = 0; k < mesh.panelCount(); ++k) {
    const auto& ix = mesh.panels[static_cast<std::size_t>(k)];
    const int n = ix[3] < 0 ? 3 : 4;
    const auto fail = [&](const std::string& why) { throw PanelError(describe(mesh, k) + ": " + why); };
    // (indices) => checked corner positions
    std::array<Vector3, 4> v;
    for (int j = 0; j < n; ++j) {
      const int a = ix[static_cast<std::size_t>(j)];
      if (a < 0 || a >= nv) fail("vertex index " + std::to_string(a) + " outside 0.." + std::to_string(nv - 1));
      v[static_cast<std::size_t>(j)] = mesh.vertices[static_cast<std::size_t>(a)];
      if (!v[static_cast<std::size_t>(j)].allFinite()) fail("vertex " + std::to_string(a) + " is not finite");
      for (int i = 0; i < j; ++i) {
        if (ix[static_cast<std::size_t>(i)] == a) fail("vertex " + std::to_string(a) + " repeated (degenerate panel)");
      }
    }
    // (corners) => normal from the diagonals (a triangle: from two edges), mean plane, diameter
    Panel p;
    p.count = n;
    const Vector3 cross = n == 3 ? Vector3((v[1] - v[0]).cross(v[2] - v[0])) : Vector3((v[2] - v[0]).cross(v[3] - v[1]));
    double diameter = 0.0;
    for (int i = 0; i < n; ++i) {
      for (int j = i + 1; j < n; ++j) diameter = std::max(diameter, (v[static_cast<std::size_t>(i)] - v[static_cast<std::size_t>(j)]).norm());
    }
    p.diameter = diameter;
    if (!(cross.norm() > 1e-10 * diameter * diameter)) fail("zero area (degenerate panel)");
    p.normal = cross.normalized();
    Vector3 mean = Vector3::Zero();
    for (int j = 0; j < n; ++j) mean += v[static_cast<std::size_t>(j)];
    mean /= n;
    for (int j = 0; j < n; ++j) {
      const auto sj = static_cast<std::size_t>(j);
      const double off = p.normal.dot(v[sj] - mean);
      if (std::abs(off) > kMaxQuadWarp * diameter) fail("quad is warped (split it into two triangles)");
      p.vertices[sj] = v[sj] - off * p.normal;
    }
    // (plane corners) => area and area centroid by the fan from corner 0; each fan triangle must
    // turn the same way as the panel (a quad folded over a diagonal or a bow-tie is refused)
    Vector3 c = Vector3::Zero();
    for (int j = 1; j + 1 < n; ++j) {
      const Vector3& a = p.vertices[0];
      const Vector3& b = p.vertices[static_cast<std::size_t>(j)];
      const Vector3& d = p.vertices[static_cast<std::size_t>(j + 1)];
      const double t = 0.5 * (b - a).cross(d - a).dot(p.normal);
      if (!(t > 1e-12 * diameter * diameter)) fail("corners do not turn one way about the normal (folded or bow-tie panel)");
      p.area += t;
      c += t * (a + b + d) / 3.0;
    }
    p.centroid = c / p.area;
    // (edges) => each directed edge used once; twice means a neighbour is oriented the other way
    for (int j = 0; j < n; ++j) {
      const std::pair<int, int> e{ix[static_cast<std::size_t>(j)], ix[static_cast<std::size_t>((j + 1) % n)]};
      const auto [it, fresh] = edgeOwner.emplace(e, k);
      if (!fresh) {
        fail("edge " + std::to_string(e.first) + " -> " + std::to_string(e.second) + " is also traversed this way by " +
             describe(mesh, it->second) + ": inconsistent orientation (normals must all point into the fluid)");
      }
    }
    out.push_back(p);
  }
  return out;
}

}  // namespace yardsim::forces::hydro
