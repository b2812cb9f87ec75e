#include "scene/resource_limits.hpp"

#include <cmath>
#include <cstdio>
#include <functional>

#include "scene/mechanical_systems.hpp"

namespace yardsim::scene {

namespace {
// (number) => "1.2e+07" style text for messages
std::string shortNumber(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

// (instance tree, visitor) => every atomic instance visited
void eachAtomic(const Instance& inst, const std::function<void(const Instance&)>& visit) {
  if (inst.atomic()) visit(inst);
  for (const auto& c : inst.children) eachAtomic(*c, visit);
}
}  // namespace

void checkResourceLimits(const Scene& scene, double until, const std::string& untilFrom,
                         models::Diagnostics& diags) {
  if (!(until > 0) || !std::isfinite(until)) return;  // no end time: bounded by the events
  const std::string end =
      (untilFrom.empty() ? "until = " : untilFrom + " ") + shortNumber(until) + " s";
  // (step s, where, key path, ceiling, what a unit is, the limits key) => an error above the
  // ceiling
  auto check = [&](const char* noun, double step, const SourceMark& where,
                   const std::string& keyPath, double ceiling, const char* what,
                   const char* limitKey) {
    if (!(step > 0)) return;
    const double count = until / step;
    if (count <= ceiling) return;
    diags.error(where, keyPath,
                std::string(noun) + " of " + shortNumber(step) + " s over " + end + " is " +
                    shortNumber(count) + " " + what + ", above the ceiling of " +
                    shortNumber(ceiling) +
                    "; take a longer step or a shorter run, or "
                    "raise the ceiling with the root key `limits: {" +
                    limitKey + ": " + shortNumber(count) + "}`");
  };
  if (!scene.systems.empty())
    check("a step", scene.dt, scene.integratorWhere, "integrator.dt", scene.limits.steps, "steps",
          "steps");
  eachAtomic(scene.root, [&](const Instance& a) {
    for (const char* key : {"dt", "period"})
      if (a.params.has(key) && a.params.node(key).IsScalar()) {
        double step = 0;
        if (YAML::convert<double>::decode(a.params.node(key), step))
          check(key[0] == 'd' ? "a step" : "a period", step, a.params.mark(key),
                a.keyPath + ".params." + key, scene.limits.steps, "steps", "steps");
      }
  });
  check("a record interval", scene.record.interval, scene.record.where, "record.interval",
        scene.limits.rows, "recorded rows", "rows");
  // (hydrodynamics with a run-length check: a marched free surface) => its problems over `until`
  for (const auto& system : scene.systems)
    for (std::size_t i = 0; i < system->spec.hydrodynamics.size(); ++i)
      if (const auto& runCheck = system->spec.hydrodynamics[i].runCheck)
        for (const std::string& problem : runCheck(until))
          diags.error(system->hydroPlaces[i].first, system->hydroPlaces[i].second,
                      problem + " (" + end + ")");
}

}  // namespace yardsim::scene
