#pragma once
// Added mass and damping at one frequency from the time-domain solver: the hull is forced to
// oscillate in one mode, xi_j(t) = xi_0 r(t) sin(w t) with a smooth ramp r(t) = (1 - cos(pi t /
// T_r)) / 2 over the first rampPeriods periods, and the steady radiation force is Fourier-
// analysed over the last analysisPeriods periods:
//   F_i = -A_ij xi_ddot - B_ij xi_dot = (A_ij - A_inf,ij) w^2 xi_0 sin(w t) - B_ij w xi_0 cos(w t)
//   + (-A_inf xi_ddot)
// so with F^M the memory force (emp_scheme.hpp),
//   A_ij = A_inf,ij + (2/T_a) int F^M_i sin(w t) dt / (xi_0 w^2),  B_ij = -(2/T_a) int F^M_i cos(w
//   t) dt / (xi_0 w).
// The free-surface elevation is Fourier-analysed the same way (its complex amplitude per panel,
// for the far-field energy balance, far_field.hpp).
// W axes about the body origin; A kg (kg m, kg m^2), B kg/s (...); w rad/s.
#include <Eigen/Core>

#include "forces/hydro/rankine_td_model.hpp"

namespace yardsim::forces::hydro {

struct ForcedOscillationSettings {
  double omega = 1.0;      ///< rad/s
  double amplitude = 1.0;  ///< xi_0, m or rad (linear: any value gives the same coefficients)
  double dt = 0.0;         ///< s; the step is shortened so that a period holds a whole number
  int rampPeriods = 3;
  int periods = 10;         ///< total, ramp included
  int analysisPeriods = 3;  ///< the last ones
};

struct RadiationCoefficients {
  Eigen::Matrix<double, 6, 1> addedMass;  ///< column `mode` of A(w)
  Eigen::Matrix<double, 6, 1> damping;    ///< column `mode` of B(w)
  double dt = 0.0;                        ///< the step used, s
  /// complex free-surface elevation per unit amplitude, one per free-surface panel:
  /// zeta(t) = Re(surfaceAmplitude e^{i w t}) xi_0 in the steady state, m per m (or per rad)
  Eigen::VectorXcd surfaceAmplitude;
};

/// (model, mode 0..5, settings) => column `mode` of A(w) and B(w).
RadiationCoefficients forcedOscillation(const RankineTdModel& model, int mode,
                                        const ForcedOscillationSettings& settings);

}  // namespace yardsim::forces::hydro
