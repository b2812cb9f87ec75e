#pragma once
// The wetted part of a hull at its mean position: every panel clipped to z <= 0 (the mean water
// plane z = 0, hull mesh given in the world frame at that position). A panel wholly below is kept
// as it is, one wholly above (or lying in the plane) is dropped, one cut by the plane keeps its
// part below (Sutherland-Hodgman); a cut that leaves five corners is split into a quad and a
// triangle. New corners on a cut edge are shared by the two panels of that edge, so the result
// stays a consistently connected mesh, open along the waterline.
#include "forces/hydro/panel_mesh.hpp"

namespace yardsim::forces::hydro {

/// (closed or open hull mesh, world frame at the mean position) => the part in z <= 0.
PanelMesh wettedSurface(const PanelMesh& hull);

}  // namespace yardsim::forces::hydro
