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

Alarm* AlarmMonitor::find(const std::string& model, const std::string& element,
                          const std::string& kind, const std::string& message) {
  auto it = std::find_if(alarms_.begin(), alarms_.end(), [&](const Alarm& a) {
    return a.model == model && a.element == element && a.kind == kind && a.message == message;
  });
  return it == alarms_.end() ? nullptr : &*it;
}

void AlarmMonitor::raise(const std::string& model, const std::string& element,
                         const std::string& kind, bool alarm, double t, double value,
                         bool occurrence) {
  Alarm* a = find(model, element, kind);
  if (a == nullptr) {
    alarms_.push_back({model, element, kind, alarm ? "alarm" : "notice", t, 1, value, t, ""});
    if (onFirst_) onFirst_(alarms_.back());
    return;
  }
  if (occurrence) ++a->count;
  const bool closest = kind == "clearance_below" || kind == "touched";  // worst: nearest
  if (closest ? value < a->worst : std::abs(value) > std::abs(a->worst)) {
    a->worst = value;
    a->worstAt = t;
  }
}

void AlarmMonitor::warn(const models::Diagnostic& d, double t, bool occurrence) {
  // (diagnostic) => its text without the severity, its element or else its key path
  models::Diagnostic plain = d;
  plain.severity = models::Diagnostic::Severity::Warning;
  std::string message = models::format(plain);
  if (const auto at = message.find(": warning: "); at != std::string::npos)
    message.replace(at, 11, ": ");
  const std::string element = d.element.empty() ? d.keyPath : d.element;
  if (Alarm* a = find("", element, "warning", message)) {
    if (occurrence) ++a->count;
    return;
  }
  alarms_.push_back({"", element, "warning", "warning", t, 1, d.value, t, message});
  if (onFirst_) onFirst_(alarms_.back());
}

void AlarmMonitor::worsen(const std::string& model, const std::string& element,
                          const std::string& kind, bool larger, double t, double value) {
  Alarm* a = find(model, element, kind);
  if (a == nullptr || !(larger ? value > a->worst : value < a->worst)) return;
  a->worst = value;
  a->worstAt = t;
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
        if (mb->state().x.peakTension[r] > a.worst) {
          a.worst = mb->state().x.peakTension[r];
          a.worstAt = mb->state().x.peakTime[r];
        }
}

std::size_t AlarmMonitor::alarmCount() const {
  return static_cast<std::size_t>(std::count_if(
      alarms_.begin(), alarms_.end(), [](const Alarm& a) { return a.severity == "alarm"; }));
}

std::size_t AlarmMonitor::warningCount() const {
  return static_cast<std::size_t>(std::count_if(
      alarms_.begin(), alarms_.end(), [](const Alarm& a) { return a.severity == "warning"; }));
}

}  // namespace yardsim::run
