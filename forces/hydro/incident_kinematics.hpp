#pragma once
// Linear (Airy) incident-wave kinematics on a finite or infinite depth, shared by the solver's
// incident terms (the rankine_td provider, the impulse responses' impulsive wave and the
// frequency domain), so that all three see the same wave:
//   phi_I = g a / w C(z) sin(theta),  C = cosh k(z + h) / cosh kh,  S = sinh k(z + h) / cosh kh,
//   grad phi_I = (g k / w) a (C cos(theta) e_beta, S sin(theta)),  w^2 = g k tanh kh.
// Units: k rad/m, z m (<= 0 below the still-water level), h m (infinity: deep water), w rad/s,
// g m/s^2.
#include <cmath>
#include <utility>

namespace yardsim::forces::hydro {

/// (k, z, h) => {C, S}: cosh k(z+h) / cosh kh and sinh k(z+h) / cosh kh, in forms that neither
/// overflow nor lose the deep-water limit e^{kz} (both).
inline std::pair<double, double> depthFactors(double k, double z, double h) {
  const double e = std::exp(k * z);
  if (!std::isfinite(h)) return {e, e};
  const double a = std::exp(-2.0 * k * (z + h)), b = std::exp(-2.0 * k * h);
  return {e * (1.0 + a) / (1.0 + b), e * (1.0 - a) / (1.0 + b)};
}

/// (w, k, h, g) => g k / w, the surface velocity per metre of elevation, 1/s (w in deep water);
/// its limit at w = 0 is sqrt(g / h) on a finite depth (the shallow-water wave) and 0 in deep
/// water.
inline double velocityPerElevation(double w, double k, double h, double g) {
  if (w > 0.0) return g * k / w;
  return std::isfinite(h) ? std::sqrt(g / h) : 0.0;
}

}  // namespace yardsim::forces::hydro
