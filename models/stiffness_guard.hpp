#pragma once
// The stiffness guard (docs/numerics.md): before a run, each mechanical system's highest
// frequency omega_max (multibody/stiffness_estimate.hpp) is compared with the chosen method's
// stability limit: omega_max dt must stay inside the method's stability region on the imaginary
// axis (RK4 2.83, semi-implicit Euler 2, AB3 0.72, AB4 0.43; explicit Euler and AB2 grow every
// undamped mode). The scene's `integrator: {stiffness_check: warn | refuse | off}` chooses a
// warning or an error; either suggests a step that works or an implicit method.
#include <limits>
#include <string>
#include <string_view>

#include "models/diagnostics.hpp"
#include "models/multibody/stiffness_estimate.hpp"
#include "models/scene.hpp"

namespace yardsim::models {

inline constexpr double kNoStabilityLimit = std::numeric_limits<double>::infinity();

// (method name) => the largest stable omega dt on the imaginary axis: 0 when every undamped
// mode grows, kNoStabilityLimit for implicit methods with unconditional stability on it and
// for adaptive ones (their error control chooses the step)
double stabilityLimit(std::string_view method);

struct StepVerdict {
  bool stable = true;
  double omegaDt = 0.0;
  double limit = kNoStabilityLimit;
  double suggestedDt = 0.0;  // a fixed step that is stable (0.9 limit / omega_max), 0 if none
  std::string problem;       // why not (empty when stable)
  std::string suggestion;    // what to do instead
  std::string message() const { return problem + "; suggestion: " + suggestion; }
};

// (estimate, method, step) => whether the step is inside the method's stability limit
StepVerdict judgeStep(const StiffnessEstimate& e, std::string_view method, double dt);

// (scene with its mechanical systems) => an error when the step is longer than the run; per
// system, a warning or an error (per scene.stiffnessCheck) when its step is beyond the
// method's stability limit
void checkStiffness(const Scene& scene, Diagnostics& diags);

}  // namespace yardsim::models
