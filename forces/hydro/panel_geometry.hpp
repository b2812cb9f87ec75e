#pragma once
// Flat panels made from a PanelMesh (Hess & Smith 1964): a quad whose four vertices are not
// coplanar is replaced by its projection on the mean plane through the vertex average, with the
// normal along the cross product of the diagonals. Each panel carries what the influence
// integrals need: projected vertices, unit normal, area, area centroid (the collocation point)
// and diameter (largest vertex distance). buildPanels refuses a degenerate panel (repeated or
// out-of-range vertex, zero area, a quad folded over its diagonal or far from planar) and
// inconsistent orientation (an edge traversed twice in the same direction), naming the panel.
#include <array>
#include <stdexcept>
#include <vector>

#include "forces/hydro/panel_mesh.hpp"

namespace yardsim::forces::hydro {

class PanelError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

struct Panel {
  std::array<Vector3, 4> vertices;  ///< on the panel plane; vertices[3] unused for a triangle
  int count = 3;                    ///< 3 or 4
  Vector3 normal = Vector3::UnitZ();  ///< unit, out of the body into the fluid
  Vector3 centroid = Vector3::Zero(); ///< area centroid, on the panel plane
  double area = 0.0;
  double diameter = 0.0;
};

/// (mesh) => flat panels in mesh order; throws PanelError naming the first bad panel (its index
/// and vertex indices).
std::vector<Panel> buildPanels(const PanelMesh& mesh);

/// A quad is refused when a vertex lies farther than this fraction of the panel diameter from
/// the mean plane (a warped quad should be split into two triangles).
inline constexpr double kMaxQuadWarp = 0.05;

}  // namespace yardsim::forces::hydro
