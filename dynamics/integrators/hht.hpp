#pragma once
// HHT-alpha (Hilber, Hughes & Taylor 1977) as a member of the generalized-alpha family
// (generalized_alpha.hpp): alpha_m = 0, alpha_f = -alpha, gamma = 1/2 - alpha,
// beta = (1 - alpha)^2 / 4, for alpha in [-1/3, 0]. alpha = 0 is the trapezoidal rule (no
// numerical damping); alpha = -1/3 damps the highest frequencies most (rho_inf = 1/2).

#include "dynamics/integrators/generalized_alpha.hpp"

namespace yardsim::dynamics {

/// (alpha in [-1/3, 0]) => the generalized-alpha parameters of HHT-alpha.
GeneralizedAlphaParameters hhtParameters(double alpha);

}  // namespace yardsim::dynamics
