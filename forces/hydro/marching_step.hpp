#pragma once
// A provider's own marching step against its stability limit, for the scene's stiffness guard
// (scene/stiffness_guard.hpp) to report beside the mechanical step's: rankine_td marches its free
// surface by the emp scheme every panel step, stable for g lambda_max dt^2 <= 4 (emp_scheme.hpp).
// Units: s, 1/m.
#include <string>

namespace yardsim::forces::hydro {

struct MarchingStep {
  std::string scheme;      // "emp": what is marched at this step
  double step = 0.0;       // s, the provider's own step (rankine_td: panel_step)
  double limit = 0.0;      // s, the largest stable step (emp: 2 / sqrt(g lambda_max))
  double lambdaMax = 0.0;  // 1/m, the largest eigenvalue of the free surface's phi -> phi_z
  double gravity = 9.80665;  // m/s^2
  // () => g lambda_max step^2: stable up to 4
  double stabilityNumber() const { return gravity * lambdaMax * step * step; }
};

}  // namespace yardsim::forces::hydro
