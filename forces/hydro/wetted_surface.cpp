#include "forces/hydro/wetted_surface.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace yardsim::forces::hydro {

PanelMesh wettedSurface(const PanelMesh& hull) {
  PanelMesh out;
  double size = 0.0;
  for (const Vector3& v : hull.vertices) size = std::max(size, v.cwiseAbs().maxCoeff());
  const double tol = 1e-12 * std::max(size, 1.0);
  std::vector<int> kept(hull.vertices.size(), -1);
  std::map<std::pair<int, int>, int> cuts;
  // (old vertex) => its index in the output
  const auto keep = [&](int a) {
    int& k = kept[static_cast<std::size_t>(a)];
    if (k < 0) {
      k = static_cast<int>(out.vertices.size());
      out.vertices.push_back(hull.vertices[static_cast<std::size_t>(a)]);
    }
    return k;
  };
  // (edge a-b crossing z = 0) => the shared crossing vertex
  const auto cut = [&](int a, int b) {
    const std::pair<int, int> key{std::min(a, b), std::max(a, b)};
    const auto it = cuts.find(key);
    if (it != cuts.end()) return it->second;
    const Vector3& pa = hull.vertices[static_cast<std::size_t>(key.first)];
    const Vector3& pb = hull.vertices[static_cast<std::size_t>(key.second)];
    const double s = pa.z() / (pa.z() - pb.z());
    Vector3 x = pa + s * (pb - pa);
    x.z() = 0.0;
    const int k = static_cast<int>(out.vertices.size());
    out.vertices.push_back(x);
    cuts.emplace(key, k);
    return k;
  };
  for (const auto& ix : hull.panels) {
    const int n = ix[3] < 0 ? 3 : 4;
    // (corners) => the polygon in z <= 0 (corners within tol of the plane count as on it)
    std::vector<int> poly;
    bool below = false;
    for (int j = 0; j < n; ++j) {
      const int a = ix[static_cast<std::size_t>(j)], b = ix[static_cast<std::size_t>((j + 1) % n)];
      const double za = hull.vertices[static_cast<std::size_t>(a)].z(), zb = hull.vertices[static_cast<std::size_t>(b)].z();
      if (za <= tol) poly.push_back(keep(a));
      if (za < -tol) below = true;
      if ((za < -tol && zb > tol) || (za > tol && zb < -tol)) poly.push_back(cut(a, b));
    }
    if (!below || poly.size() < 3) continue;
    // (polygon of 3 to 5 corners) => a triangle, a quad, or a quad and a triangle
    if (poly.size() == 3) out.addTriangle(poly[0], poly[1], poly[2]);
    else if (poly.size() == 4) out.addQuad(poly[0], poly[1], poly[2], poly[3]);
    else {
      out.addQuad(poly[0], poly[1], poly[2], poly[3]);
      out.addTriangle(poly[0], poly[3], poly[4]);
    }
  }
  return out;
}

}  // namespace yardsim::forces::hydro
