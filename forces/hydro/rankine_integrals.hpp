#pragma once
// Integrals of the Rankine source 1/r and of its normal dipole over one flat panel, seen from a
// field point x (r = |x - q|, q on the panel, n the panel normal):
//   source  S(x) = int 1/r dA
//   dipole  D(x) = int d/dn_q (1/r) dA = int n.(x - q) / r^3 dA
// D is minus the solid angle the panel subtends at x (a closed surface with outward normals:
// sum of D = -4 pi inside, 0 outside). Near the panel both are exact for a flat polygon:
//   D = sum over the fan triangles of -2 atan2(R1.(R2 x R3), r1 r2 r3 + (R1.R2) r3 + (R1.R3) r2
//       + (R2.R3) r1)   (van Oosterom & Strackee 1983; the same solid angle as Newman's 1986
//       arctangent sum over the edges, without its singular edge slopes)
//   S = sum_k p_k ln((r_k + r_k+1 + d_k) / (r_k + r_k+1 - d_k)) - Z D   (Newman 1986;
//       Hess & Smith 1964), p_k the in-plane distance of x from edge k (positive inside), d_k the
//       edge length, Z = n.(x - centroid).
// Farther than kFarField panel diameters from the centroid c they take the one-point rule
//   S = A / |x - c|,  D = A n.(x - c) / |x - c|^3,
// whose error there is below 1e-3 A/R for S and 5e-3 A/R^2 for D (R the distance; it falls as
// (diameter / R)^2, the area centroid cancelling the first moments; tested).
// On the panel plane (|Z| below 1e-12 diameters) D is 0: the principal value at the panel's own
// collocation point, and the exact value outside the polygon.
#include "forces/hydro/panel_geometry.hpp"

namespace yardsim::forces::hydro {

/// Beyond this many panel diameters from the centroid the one-point rule replaces the exact
/// integrals.
inline constexpr double kFarField = 4.0;

struct PanelIntegrals {
  double source = 0.0;
  double dipole = 0.0;
};

/// (panel, x) => exact S and D.
PanelIntegrals exactIntegrals(const Panel& p, const Vector3& x);
/// (panel, x) => one-point S and D.
PanelIntegrals onePointIntegrals(const Panel& p, const Vector3& x);
/// True when x is farther than kFarField diameters from the centroid.
inline bool isFarField(const Panel& p, const Vector3& x) {
  return (x - p.centroid).squaredNorm() > kFarField * kFarField * p.diameter * p.diameter;
}
/// (panel, x) => S and D, exact near the panel and by the one-point rule far from it.
inline PanelIntegrals panelIntegrals(const Panel& p, const Vector3& x) {
  return isFarField(p, x) ? onePointIntegrals(p, x) : exactIntegrals(p, x);
}
/// (panel, x) => grad_x S, the velocity induced at x by a unit source density on the panel:
/// exact near (sum_k (n x t_k) ln(...) - n D, t_k the unit edge direction), one-point far.
Vector3 sourceGradient(const Panel& p, const Vector3& x);

}  // namespace yardsim::forces::hydro
