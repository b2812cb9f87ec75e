#pragma once
// Panels on the mean free surface z = 0 around the mean wetted hull, out to a truncation radius,
// with the damping zone ("numerical beach") over the outer annulus. World frame at the mean
// position, z up, the hull's wetted part in z <= 0 (wettedSurface). Lengths m, rates 1/s.
//
// The rings follow the waterline: the waterline loop (the wetted hull's open edges on z = 0) is
// read in azimuth order about its vertex average c, which needs a waterline star-shaped about c
// (every ray from c crosses it once; a convex waterline is). Ring m puts one vertex on the ray
// through each waterline vertex k at distance r_k + t_m (R - r_k) from c, R the truncation radius
// and r_k the waterline vertex's distance, so ring 0 is the waterline and the last ring the circle
// of radius R. The ring spacing, measured along the mean waterline radius, starts at
// firstSpacing, grows by the factor growth and stops growing at maxSpacing (inside the damping
// zone at beachSpacing, when given). Panel normals point into the fluid (-z), as on the body.
//
// Azimuthal refinement (azimuthSpacing > 0): the rays through the waterline vertices fan out, so
// far from the hull a panel between two rays grows wide in azimuth. A row's panel between rays k
// and k + 1 is then split into 2^j equal panels along its edges, the fewest that make its edges
// no longer than azimuthSpacing (inside the damping zone's inner edge) or beachSpacing (inside the
// zone; azimuthSpacing there too without it). The split panels cover exactly the unsplit one; where
// the splits of two neighbouring rows differ, the finer row's corners lie on the coarser row's
// straight edge (hanging corners: the constant-strength panels need no shared corners). Without
// azimuthSpacing the mesh is the unrefined one, vertex for vertex.
//
// Damping zone: over the outer annulus of width dampingWidth the free-surface conditions become
//   zeta_t = phi_z - 2 nu zeta + nu^2 phi / g,   phi_t = -g zeta,
// which turns a plane wave exp(i(k x - w t)) into w = +-sqrt(g k) - i nu: damped at the rate nu
// with its real frequency unchanged. nu(r) = dampingStrength ((r - (R - dampingWidth)) /
// dampingWidth)^2 rises smoothly from 0 at the inner edge of the annulus.
// surfaceDamping nu0 is added to nu on every panel, in the same form: it multiplies every free
// solution by e^(-nu0 t) and keeps the real frequencies; a nu0 above the growth rate of the
// mesh's short-wave modes (surface_growth.hpp) keeps a long marched run bounded.
#include <stdexcept>
#include <vector>

#include "forces/hydro/panel_mesh.hpp"

namespace yardsim::forces::hydro {

/// The most free-surface panels a mesh may have: the dense mixed problem holds 2 N^2 doubles
/// while it is set up (about 7 GB at 20,000); a setting that asks for more is refused before the
/// mesh is made.
inline constexpr int kMaxFreeSurfacePanels = 20000;

struct FreeSurfaceSettings {
  double truncationRadius = 0.0;  ///< R, m, from the waterline centre
  double firstSpacing = 0.0;      ///< m, width of the ring next to the hull
  double maxSpacing = 0.0;        ///< m, ring width far from the hull
  double growth = 1.15;           ///< ratio of neighbouring ring widths (>= 1)
  double dampingWidth = 0.0;      ///< m, width of the damping annulus (0: none)
  double dampingStrength = 0.0;   ///< nu at the truncation radius, 1/s
  double surfaceDamping = 0.0;    ///< nu0 added on every panel, 1/s (0: none)
  double azimuthSpacing = 0.0;  ///< m, widest panel edge along a ring inside the zone (0: no split)
  double beachSpacing =
      0.0;  ///< m, ring width (and azimuthal edge) inside the zone (0: maxSpacing)
};

/// (period of the longest relevant wave T, s; g) => a damping zone one deep-water wavelength
/// g T^2 / (2 pi) wide with nu_max = 2 pi / T, the settings this project uses by default.
FreeSurfaceSettings defaultBeach(FreeSurfaceSettings s, double longestPeriod, double g = 9.80665);

struct FreeSurfaceMesh {
  PanelMesh mesh;                    ///< quads on z = 0, normals -z
  std::vector<double> damping;       ///< nu per panel (at its centroid), 1/s
  Vector3 centre = Vector3::Zero();  ///< waterline vertex average c (z = 0)
  double waterlineRadius = 0.0;      ///< largest r_k, m
};

/// A waterline the free-surface mesh cannot follow (no closed loop, several loops, not
/// star-shaped), or settings that do not fit (the hull reaching the truncation radius).
class FreeSurfaceError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// (wetted hull in z <= 0) => its waterline vertex indices as one closed loop, counter-clockwise
/// seen from above; throws FreeSurfaceError when the open edges on z = 0 do not form one loop.
std::vector<int> waterlineLoop(const PanelMesh& wetted);

/// (wetted hull, settings) => the free-surface panels and their damping; throws
/// FreeSurfaceError with the numbers when the hull reaches the truncation radius, the waterline
/// is not star-shaped about its centre, or the settings ask for more than kMaxFreeSurfacePanels.
FreeSurfaceMesh buildFreeSurface(const PanelMesh& wetted, const FreeSurfaceSettings& settings);

}  // namespace yardsim::forces::hydro
