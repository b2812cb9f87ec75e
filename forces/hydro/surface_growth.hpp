#pragma once
// The growth rate of the marched free surface's own (unforced) solutions. The discrete operator
// phi -> phi_z of constant panels with centroid collocation is not symmetric and a few of its
// eigenvalues lie off the real axis; in the continuous-time emp system with the hull held,
//   zeta_t = phi_z - 2 nu zeta + nu^2 phi / g,   phi_t = -g zeta        (nu per panel, 1/s),
// they become eigenvalues s with a small positive real part: short waves (shorter than the mesh
// carries) that grow as e^(Re s t) and spoil a marched run longer than some 1/Re s
// (docs/hydrodynamics.md, "Limits of the time-domain solver").
//
// A uniform damping nu0 added to nu in the beach's form (FreeSurfaceSettings::surfaceDamping)
// multiplies every free solution by e^(-nu0 t) exactly: with nu = nu_b + nu0 and phi = e^(-nu0 t)
// psi, psi obeys the system of nu_b alone. So it lowers every growth rate by nu0 and keeps the
// real frequencies.
//
// Units: rates 1/s, frequencies rad/s; the model's frame (world axes at the mean pose).
#include "forces/hydro/rankine_td_model.hpp"

namespace yardsim::forces::hydro {

struct SurfaceGrowth {
  double rate = 0.0;       ///< 1/s, the largest growth rate (< 0: all decay)
  double frequency = 0.0;  ///< rad/s, the frequency of that mode
  int panels = 0;          ///< free-surface panels (the dense eigenvalue problem is 2 x that)
};

/// (model, emp step dt s, or 0) => the largest growth rate of the hull-held emp system of its
/// free surface, per eigenvalue lambda of L: phi -> phi_z the 2 x 2 system of its mode with the
/// uniform damping nu0: continuous (dt = 0: Re s = |Im sqrt(g lambda)| - nu0), or one emp step
/// (ln|z| / dt for the step's eigenvalue z: the scheme adds growth at a step near its limit,
/// 0.0092 against 0.0070 1/s at 0.25 s on the barge's 2 rad/s mesh; measured in a march). The beach
/// is left out (it only damps: on the box barge's meshes the full system of order 2 Nf with the
/// beach has the same largest rate to the 5 digits printed, at 14 times the cost). Dense: Nf solves
/// with the model's factors and an eigenvalue solve of order Nf, O(Nf^3) (about 1 s of CPU at 640
/// panels, 0.2 s at 580).
SurfaceGrowth surfaceGrowth(const RankineTdModel& model, double dt = 0.0);

}  // namespace yardsim::forces::hydro
