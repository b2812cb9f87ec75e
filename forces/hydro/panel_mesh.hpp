#pragma once
// A hull surface as plain arrays: vertices and flat panels (triangles and quads) given by vertex
// indices, counter-clockwise seen from the fluid (the normal by the right-hand rule points out of
// the body into the fluid). The panel solver reads only this; a triangle mesh read from OBJ/STL
// converts into it by copying indices.
#include <array>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "forces/geometry/triangle_mesh.hpp"

namespace yardsim::forces::hydro {

using Vector3 = Eigen::Vector3d;

struct PanelMesh {
  std::vector<Vector3> vertices;
  /// Vertex indices of each panel; a triangle has index[3] = -1.
  std::vector<std::array<int, 4>> panels;

  int panelCount() const { return static_cast<int>(panels.size()); }
  /// Appends a triangle (a, b, c) or a quad (a, b, c, d).
  void addTriangle(int a, int b, int c) { panels.push_back({a, b, c, -1}); }
  void addQuad(int a, int b, int c, int d) { panels.push_back({a, b, c, d}); }
};

/// (triangle mesh, outward counter-clockwise triangles) => the same surface as triangle panels.
inline PanelMesh panelMesh(const TriangleMesh& mesh) {
  PanelMesh p;
  p.vertices = mesh.vertices;
  p.panels.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) p.addTriangle(t[0], t[1], t[2]);
  return p;
}

}  // namespace yardsim::forces::hydro
