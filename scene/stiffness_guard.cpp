#include "scene/stiffness_guard.hpp"

#include <cmath>
#include <cstdio>
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

namespace {

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

// (system, its mechanical verdict, scene) => per marched provider (rankine_td's free surface) its
// own step against its stability limit, beside the mechanical step's: above the limit, within
// kMarchingMargin of it, or not a whole multiple of the mechanics step (the march is taken at the
// start of a mechanics step, so it would fall behind the run) is a warning or an error
void checkMarching(const MechanicalSystem& system, const StepVerdict& mechanical, const Scene& scene,
                   Diagnostics& diags) {
  const auto& hydro = system.spec.hydrodynamics;
  for (std::size_t i = 0; i < hydro.size(); ++i) {
    if (!hydro[i].marchingStep) continue;
    const auto& [where, key] = system.hydroPlaces[i];
    forces::hydro::MarchingStep m;
    try {
      m = hydro[i].marchingStep();
    } catch (const std::exception& ex) {
      diags.error(where, key, std::string("its marching step could not be judged: ") + ex.what());
      continue;
    }
    // (step, limit) => the problems, each with both numbers
    std::vector<std::string> problems;
    const double ratio = m.limit > 0 ? m.step / m.limit : std::numeric_limits<double>::infinity();
    const std::string figures = "panel step " + number(m.step) + " s against the " + m.scheme +
                                " limit " + number(m.limit) + " s of its free surface (g lambda_max dt^2 = " +
                                number(m.stabilityNumber()) + ", stable up to 4; lambda_max " +
                                number(m.lambdaMax) + " 1/m)";
    if (ratio > 1.0)
      problems.push_back(figures + ": the march grows; suggestion: settings.panel_step <= " +
                         number(kMarchingMargin * m.limit) + " s");
    else if (ratio > kMarchingMargin)
      problems.push_back(figures + ": within " + number(100 * (1 - kMarchingMargin)) +
                         " % of the limit, whose lambda_max is a power-iteration estimate (from "
                         "below) without the damping zone's terms; suggestion: settings.panel_step <= " +
                         number(kMarchingMargin * m.limit) + " s");
    const double multiple = scene.dt > 0 ? m.step / scene.dt : 1.0;
    if (std::abs(multiple - std::round(multiple)) > 1e-6 * multiple || multiple < 0.5)
      problems.push_back("panel step " + number(m.step) + " s is not a whole multiple of the mechanics step " +
                         number(scene.dt) + " s: the free surface is marched by " + number(m.step) +
                         " s at the first mechanics step after each panel time and falls out of step "
                         "with the run; suggestion: settings.panel_step " +
                         number(std::max(1.0, std::round(multiple)) * scene.dt) + " s");
    const std::string mechanics = "; the mechanics step: " + scene.integrator + " at dt = " + number(scene.dt) +
                                  " s, omega_max dt = " + number(mechanical.omegaDt) +
                                  (mechanical.limit == mechanics::kNoStabilityLimit
                                       ? std::string(" (no limit)")
                                       : " against its limit " + number(mechanical.limit));
    for (const std::string& p : problems) {
      const std::string msg = "hydrodynamics '" + hydro[i].name + "' of mechanical system '" + system.name +
                              "': " + p + mechanics;
      if (scene.stiffnessCheck == "refuse")
        diags.error(where, key, msg + " (stiffness_check: refuse)");
      else
        diags.warning(where, key,
                      msg + " (stiffness_check: warn; `refuse` makes this an error, `off` silences it)",
                      {}, hydro[i].name, ratio);
    }
  }
}

}  // namespace

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
    checkMarching(*system, v, scene, diags);
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
