#include "models/stiffness_guard.hpp"

#include <cmath>
#include <sstream>

#include "dynamics/integrators/factory.hpp"
#include "models/mechanical_systems.hpp"

namespace yardsim::models {

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

void checkStiffness(const Scene& scene, Diagnostics& diags) {
  if (scene.systems.empty() || !(scene.dt > 0)) return;
  // (step, end time) => a step longer than the whole run integrates nothing
  if (scene.dt > scene.until) {
    std::ostringstream s;
    s << "the step " << scene.dt << " s is longer than the whole run (until: " << scene.until
      << " s): nothing would be integrated";
    std::ostringstream hint;
    hint << "use dt <= until, e.g. dt: " << scene.until / 100.0;
    diags.error(scene.integratorWhere, "integrator.dt", s.str(), hint.str());
  }
  if (scene.stiffnessCheck == "off") return;
  for (const auto& system : scene.systems) {
    // (system) => its estimate and the verdict on the scene's step
    StiffnessEstimate e;
    try {
      e = estimateStiffness(buildMechanics(system->spec));
    } catch (const std::exception& ex) {
      diags.error(scene.integratorWhere, "integrator",
                  "mechanical system '" + system->name + "': its accelerations at the start are not "
                  "finite: " + ex.what());
      continue;
    }
    const StepVerdict v = judgeStep(e, scene.integrator, scene.dt);
    if (v.stable) continue;
    const std::string msg = "mechanical system '" + system->name + "': " + v.message();
    if (scene.stiffnessCheck == "refuse")
      diags.error(scene.integratorWhere, "integrator.dt", msg + " (stiffness_check: refuse)");
    else
      diags.warning(scene.integratorWhere, "integrator.dt",
                    msg + " (stiffness_check: warn; `refuse` makes this an error, `off` silences it)");
  }
}

}  // namespace yardsim::models
