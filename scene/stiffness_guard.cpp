#include "scene/stiffness_guard.hpp"

#include <cmath>
#include <sstream>

#include "mechanics/build.hpp"
#include "dynamics/integrators/factory.hpp"
#include "scene/mechanical_systems.hpp"

namespace yardsim::scene {

using mechanics::StepVerdict;
using mechanics::StiffnessEstimate;
using mechanics::buildMechanics;
using mechanics::estimateStiffness;
using mechanics::judgeStep;
using models::Diagnostics;

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
      const auto& set = system->spec.settings;
      const mechanics::ServoSettings servo{set.driveBandwidth > 0 ? set.driveBandwidth : std::min(10.0, 0.1 / scene.dt),
                                           set.driveMaxEffort, set.driveTolerance};
      e = estimateStiffness(system->built ? *system->built : buildMechanics(system->spec), servo);
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
      diags.warning(
          scene.integratorWhere, "integrator.dt",
          msg + " (stiffness_check: warn; `refuse` makes this an error, `off` silences it)", {},
          e.body.empty() ? system->name : e.body, v.omegaDt);
  }
}

}  // namespace yardsim::scene
