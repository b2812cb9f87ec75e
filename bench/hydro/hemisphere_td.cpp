// Forced surge and heave of a floating hemisphere (a = 1 m) by the time-domain Rankine solver at
// ka = 0.1 .. 3: added mass and damping scaled as Hulme (1982), as CSV for
// plot_hemisphere_td.py (docs/hydrodynamics.md). Usage: hydro_hemisphere_td [n] > hemisphere_td.csv
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>

#include "forces/hydro/emp_scheme.hpp"
#include "forces/hydro/forced_oscillation.hpp"
#include "forces/hydro/hull_shapes.hpp"

using namespace yardsim::forces::hydro;

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 10;
  const double g = 9.80665, rho = 1025.0, scale = rho * 2.0 / 3.0 * std::numbers::pi;
  std::printf("mode,ka,A,B,N_body,N_surface\n");
  for (const double ka : {0.1, 0.2, 0.3, 0.4, 0.6, 0.8, 1.0, 1.2, 1.4, 1.7, 2.0, 2.5, 3.0}) {
    // (ka) => free surface 3 wavelengths out (at least 15 m), panels a tenth of a wavelength far
    // out (at most 4 m), a damping zone one wavelength wide
    const double lambda = 2.0 * std::numbers::pi / ka, omega = std::sqrt(g * ka),
                 period = 2.0 * std::numbers::pi / omega;
    RankineTdSettings s;
    s.rho = rho;
    s.g = g;
    s.freeSurface.firstSpacing = 0.15;
    s.freeSurface.maxSpacing = std::min(lambda / 12.0, 4.0);
    s.freeSurface.growth = 1.12;
    s.freeSurface.truncationRadius = 1.0 + std::max(3.0 * lambda, 15.0);
    s.freeSurface = defaultBeach(s.freeSurface, period, g);
    s.freeSurface.dampingWidth =
        std::min(s.freeSurface.dampingWidth, s.freeSurface.truncationRadius - 1.0 - 2.0 * lambda);
    const RankineTdModel model(cubeSphere(1.0, n), yardsim::dynamics::Transform{}, s);
    ForcedOscillationSettings f;
    f.omega = omega;
    f.dt = std::min(0.9 * empLimit(model, 60).dtMax, period / 60.0);
    for (const int mode : {0, 2}) {
      const RadiationCoefficients r = forcedOscillation(model, mode, f);
      std::printf("%s,%.2f,%.5f,%.5f,%d,%d\n", mode == 0 ? "surge" : "heave", ka,
                  r.addedMass[mode] / scale, r.damping[mode] / (scale * omega),
                  model.problem().bodyCount(), model.problem().surfaceCount());
      std::fflush(stdout);
    }
  }
}
