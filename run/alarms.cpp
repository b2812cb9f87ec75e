#include "run/alarms.hpp"

#include <algorithm>
#include <cmath>

#include "devs/atomic.hpp"
#include "devs/coupled.hpp"
#include "devs/port.hpp"
#include "models/multibody/messages.hpp"
#include "models/multibody/multibody_model.hpp"

namespace yardsim::run {

void AlarmMonitor::onOutput(devs::Time t, const devs::AtomicBase& m, const devs::PortBase& port) {
  // (events of a multibody model) => the safety ones counted
  const auto* events = dynamic_cast<const devs::Port<models::MechanicsEvent>*>(&port);
  if (events == nullptr || port.name() != "event") return;
  for (const models::MechanicsEvent& e : events->values()) {
    const bool alarm = e.what == "over_mbl" || e.what == "crossed" || e.what == "clearance_below" ||
                       e.what == "touched";
    const bool notice =
        e.what == "slack" || e.what == "taut" || e.what == "contact" || e.what == "release";
    if (alarm || notice) raise(m.path(), e.element, e.what, alarm, t, e.value);
  }
}

void AlarmMonitor::raise(const std::string& model, const std::string& element,
                         const std::string& kind, bool alarm, double t, double value,
                         bool occurrence) {
  auto it = std::find_if(alarms_.begin(), alarms_.end(), [&](const Alarm& a) {
    return a.model == model && a.element == element && a.kind == kind;
  });
  if (it == alarms_.end()) {
    alarms_.push_back({model, element, kind, alarm ? "alarm" : "notice", t, 1, value});
    if (onFirst_) onFirst_(alarms_.back());
    return;
  }
  if (occurrence) ++it->count;
  const bool closest = kind == "clearance_below" || kind == "touched";  // worst: nearest
  if (closest ? value < it->worst : std::abs(value) > std::abs(it->worst)) it->worst = value;
}

void raiseToRopePeaks(std::vector<Alarm>& alarms, const devs::Model& root) {
  if (!root.isAtomic()) {
    for (const auto& c : static_cast<const devs::Coupled&>(root).components())
      raiseToRopePeaks(alarms, *c);
    return;
  }
  const auto* mb = dynamic_cast<const models::MultibodyModel*>(&root);
  if (mb == nullptr) return;
  // (ropes of this model) => their running peaks onto their over_mbl alarms
  for (std::size_t r = 0; r < mb->system().ropes().size(); ++r)
    for (Alarm& a : alarms)
      if (a.kind == "over_mbl" && a.model == mb->path() && a.element == mb->rope(r).name())
        a.worst = std::max(a.worst, mb->state().x.peakTension[r]);
}

std::size_t AlarmMonitor::alarmCount() const {
  return static_cast<std::size_t>(std::count_if(
      alarms_.begin(), alarms_.end(), [](const Alarm& a) { return a.severity == "alarm"; }));
}

}  // namespace yardsim::run
