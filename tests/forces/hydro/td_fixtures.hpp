#pragma once
// Shared set-ups of the time-domain Rankine tests: a floating hemisphere of radius 1 m (the lower
// half of a cube sphere, 3 n^2 quads) with a free surface sized for a wave number k.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "forces/hydro/hull_shapes.hpp"
#include "forces/hydro/rankine_td_model.hpp"

namespace yardsim::forces::hydro::test {

inline constexpr double kG = 9.80665;
inline constexpr double kRho = 1025.0;
/// rho (2/3) pi a^3 for a = 1: Hulme's scale of the hemisphere's added mass
inline constexpr double kHemisphereMass = kRho * 2.0 / 3.0 * std::numbers::pi;

/// (ka, truncation radius in wavelengths, panels per wavelength far out) => settings for a = 1:
/// first ring 0.2 m, growth 1.15, a damping zone one wavelength wide (at most R - a - 2 lambda).
inline RankineTdSettings hemisphereSettings(double ka, double wavelengths = 3.0,
                                            double perWavelength = 10.0) {
  const double k = ka, lambda = 2.0 * std::numbers::pi / k,
               period = 2.0 * std::numbers::pi / std::sqrt(kG * k);
  RankineTdSettings s;
  s.rho = kRho;
  s.g = kG;
  s.freeSurface.firstSpacing = 0.2;
  s.freeSurface.maxSpacing = std::min(lambda / perWavelength, 4.0);
  s.freeSurface.growth = 1.15;
  s.freeSurface.truncationRadius = 1.0 + wavelengths * lambda;
  s.freeSurface = defaultBeach(s.freeSurface, period, kG);
  s.freeSurface.dampingWidth =
      std::min(s.freeSurface.dampingWidth, s.freeSurface.truncationRadius - 1.0 - 2.0 * lambda);
  return s;
}

}  // namespace yardsim::forces::hydro::test
