#pragma once
// Panel meshes of simple closed hulls made in code (validation cases and quick scenes): normals
// out of the body, vertices shared between neighbouring panels.
#include "forces/hydro/panel_mesh.hpp"

namespace yardsim::forces::hydro {

/// (radius a, divisions n per cube edge) => a sphere centred at the origin as an equiangular cube
/// sphere: 6 n^2 quads with corners on the sphere (n = 16: 1,536 panels; n = 26: 4,056).
PanelMesh cubeSphere(double radius, int n);
/// (radius, z of bottom and top, divisions around, along the axis, along the radius of the end
/// discs) => a vertical circular cylinder on the z axis: side quads, end discs of quad rings
/// around a triangle fan. Rows of side vertices sit at zBottom + k (zTop - zBottom) / nAxial.
PanelMesh verticalCylinder(double radius, double zBottom, double zTop, int nAround, int nAxial, int nRadial);

}  // namespace yardsim::forces::hydro
