#include "scene/event_checks.hpp"

#include <algorithm>
#include <set>
#include <sstream>

#include "dynamics/data.hpp"
#include "dynamics/kinematics.hpp"
#include "mechanics/system.hpp"
#include "scene/coupling_graph.hpp"
#include "scene/mechanical_systems.hpp"

namespace yardsim::scene {

std::vector<std::string> systemEventNames(const MechanicalSystem& system) {
  std::vector<std::string> out;
  if (!system.built) return out;
  const mechanics::BuiltMechanics& b = *system.built;
  for (const auto& joint : b.jointNames)
    if (!joint.empty()) out.push_back(joint + ".reached");
  // (the system, providers built) => its ropes, equalizers and provider events
  const mechanics::System sys(b, {}, system.name);
  for (const auto& rope : sys.ropes())
    for (const char* kind : {"taut", "slack", "over_mbl", "done"})
      out.push_back(rope->name() + "." + kind);
  for (const auto& watch : b.watches) out.push_back(watch.name + ".crossed");
  for (const forces::ProviderEvent* e : sys.providerEvents()) {
    out.push_back(e->element + "." + e->rising);
    if (!e->falling.empty()) out.push_back(e->element + "." + e->falling);
  }
  return out;
}

void checkStopOn(const Scene& scene, models::Diagnostics& diags) {
  const CouplingIndex index(scene.root);
  std::vector<std::string> names;  // every system's events, built at the first stop_on
  bool known = false;
  for (const Instance* a : index.atomics()) {
    if (!a->params.has("stop_on") || a->params.node("stop_on").IsNull()) continue;
    if (!known) {
      std::set<std::string> all;
      for (const auto& s : scene.systems)
        for (auto& n : systemEventNames(*s)) all.insert(std::move(n));
      names.assign(all.begin(), all.end());
      known = true;
    }
    for (const std::string& name : a->params.strings("stop_on")) {
      // (name) => matches a full event name, or a trailing part of one (as the actor matches)
      const bool found = std::any_of(names.begin(), names.end(), [&](const std::string& full) {
        return full == name || (full.size() > name.size() && full.ends_with("." + name));
      });
      if (found) continue;
      std::string valid;
      for (const auto& n : names) valid += (valid.empty() ? "" : ", ") + n;
      const std::string hint = models::didYouMean(name, names);
      diags.error(a->params.mark("stop_on"), a->keyPath + ".params.stop_on",
                  "no event '" + name + "' in the scene's mechanical systems (the valid names: " +
                      (valid.empty() ? std::string("none") : valid) + ")",
                  hint);
    }
  }
}

void checkEventsAtStart(const Scene& scene, models::Diagnostics& diags) {
  for (const auto& system : scene.systems) {
    // (systems with a provider built from the whole system: collision sets) => checked
    if (!system->built ||
        std::none_of(system->built->providers.begin(), system->built->providers.end(),
                     [](const auto& p) { return bool(p.buildFromSystem); }))
      continue;
    const mechanics::BuiltMechanics& b = *system->built;
    const mechanics::System sys(b, {}, system->name);
    if (sys.providerEvents().empty()) continue;
    // (initial state as given) => its kinematics, the stage the event functions read
    dynamics::Data data(b.model);
    dynamics::forwardKinematics(b.model, data, b.q0, b.v0);
    const forces::Stage stage{0.0, b.model, data, b.q0, b.v0};
    for (const forces::ProviderEvent* e : sys.providerEvents()) {
      if (!e->falling.empty() || !(e->g(stage) > 0.0)) continue;
      std::ostringstream s;
      s << "mechanical system '" << system->name << "': '" << e->element << "' is past its '"
        << e->rising << "' event at the start (value " << (e->value ? e->value(stage) : 0.0)
        << (e->detail ? "; " + e->detail(stage) : std::string()) << "): events are located on "
        << "crossings only, so none is raised until it comes back and crosses again";
      const bool top = e->element.find('.') == std::string::npos;
      diags.warning(scene.root.where,
                    top ? "clearance." + e->element : "mechanics.collision." + e->element, s.str());
    }
  }
}

}  // namespace yardsim::scene
