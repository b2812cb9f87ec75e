#pragma once
// A step judged against a method's stability limit (docs/numerics.md): omega_max dt must stay
// inside the method's stability region on the imaginary axis (RK4 2.83, semi-implicit Euler 2,
// AB3 0.72, AB4 0.43; explicit Euler and AB2 grow every undamped mode). Used by the stiffness
// guard before a run and by the blow-up diagnosis during it.
#include <limits>
#include <string>
#include <string_view>

#include "mechanics/stiffness_estimate.hpp"

namespace yardsim::mechanics {

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

}  // namespace yardsim::mechanics
