#pragma once
// The far-field energy balance of a radiation problem: the mean power carried away by the
// outgoing waves through a control cylinder r = const about the waterline centre, from the
// free-surface elevation of the time-domain solver alone (not from the hull force):
//   P(r) = 1/2 rho g c_g  int_0^2pi |zeta_hat(r, theta)|^2 r dtheta
// (the energy flux of a locally plane progressive wave, E c_g with E = 1/2 rho g |zeta_hat|^2),
// averaged over an annulus [rInner, rOuter] of free-surface panels (the panel areas as weights),
// with c_g the group velocity of linear waves on the solver's depth. For a forced motion of unit
// amplitude the power equals 1/2 B w^2 (the work of the damping force), so B = 2 P / w^2 is an
// independent check of the damping from the force. Valid where the local (evanescent) field has
// died out (a wavelength or so from the hull) and before the damping zone.
// Units: zeta_hat m per unit motion amplitude (m or rad), r m, omega rad/s, P W per amplitude^2.
#include <Eigen/Core>

#include "forces/hydro/rankine_td_model.hpp"

namespace yardsim::forces::hydro {

/// (omega rad/s, depth m (inf: deep), g) => group velocity of linear waves, m/s
double groupVelocity(double omega, double depth, double g);

/// (model, complex elevation per free-surface panel (forced_oscillation.hpp), omega, annulus
/// radii about the free surface's centre) => mean radiated power P, W per unit amplitude^2.
/// Throws std::invalid_argument when the sizes differ or no panel lies in the annulus.
double radiatedPower(const RankineTdModel& model, const Eigen::VectorXcd& surfaceAmplitude,
                     double omega, double rInner, double rOuter);

}  // namespace yardsim::forces::hydro
