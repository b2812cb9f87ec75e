#include "mechanics/step_verdict.hpp"

#include <cmath>
#include <sstream>

#include "dynamics/integrators/factory.hpp"

namespace yardsim::mechanics {

double stabilityLimit(std::string_view method) {
  // (method table) => the intersection of its stability region with the imaginary axis
  if (const dynamics::MethodInfo* m = dynamics::findMethod(method)) return m->imagStabilityLimit;
  return kNoStabilityLimit;  // unknown here: the scene check reports the name
}

StepVerdict judgeStep(const StiffnessEstimate& e, std::string_view method, double dt) {
  StepVerdict v;
  v.limit = stabilityLimit(method);
  v.omegaDt = e.omegaMax * dt;
  if (v.limit == kNoStabilityLimit || e.omegaMax <= 0.0) return v;
  const bool undampedGrowth = v.limit == 0.0;
  if (!undampedGrowth && v.omegaDt < v.limit) return v;
  v.stable = false;
  std::ostringstream s;
  s.precision(3);
  s << method << " at dt = " << dt << " s: " << describe(e) << ", omega_max dt = " << v.omegaDt;
  std::ostringstream fix;
  fix.precision(2);
  if (undampedGrowth) {
    s << "; " << method << " amplifies every undamped oscillation";
    fix << "rk4 at dt <= ";
    v.suggestedDt = 0.9 * stabilityLimit("rk4") / e.omegaMax;
  } else {
    s << " exceeds its stability limit " << v.limit;
    fix << "dt <= ";
    v.suggestedDt = 0.9 * v.limit / e.omegaMax;
  }
  // (step) => rounded down to two significant digits
  const double mag = std::pow(10.0, std::floor(std::log10(v.suggestedDt)) - 1.0);
  v.suggestedDt = std::floor(v.suggestedDt / mag) * mag;
  fix << v.suggestedDt << " s, or an implicit method (hht, generalized_alpha, cvode_bdf)";
  v.problem = s.str();
  v.suggestion = fix.str();
  return v;
}

}  // namespace yardsim::mechanics
