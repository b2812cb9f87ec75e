#include "run/hook_load_monitor.hpp"

#include <cmath>
#include <stdexcept>

namespace yardsim::run {

double hookLoadCapacity(const std::vector<std::pair<double, double>>& curve, double outreach) {
  if (curve.empty()) return 0.0;
  if (outreach <= curve.front().first) return curve.front().second;
  for (std::size_t i = 1; i < curve.size(); ++i) {
    const auto& [r0, c0] = curve[i - 1];
    const auto& [r1, c1] = curve[i];
    if (outreach <= r1) return r1 > r0 ? c0 + (c1 - c0) * (outreach - r0) / (r1 - r0) : c1;
  }
  return 0.0;  // beyond the curve: not rated
}

HookLoadMonitor::HookLoadMonitor(const std::vector<scene::HookLoadCheck>& checks,
                                 const std::vector<models::Channel>& channels, AlarmMonitor& alarms)
    : alarms_(alarms) {
  // (full channel name) => its read function
  auto read = [&](const std::string& name) {
    for (const auto& c : channels)
      if (c.name == name) return c.read;
    throw std::invalid_argument("hook-load check: no channel '" + name + "'");
  };
  for (const auto& check : checks) {
    Crane c{&check, {}, read(check.root + ".x"), read(check.root + ".y"), {}, false};
    for (const auto& [rope, parts] : check.ropes)
      c.tensions.emplace_back(read(rope + ".tension"), parts);
    for (const auto& body : check.hoists)
      c.hoists.emplace_back(read(body + ".x"), read(body + ".y"));
    cranes_.push_back(std::move(c));
  }
}

void HookLoadMonitor::onTransition(devs::Time t, const devs::AtomicBase& m, devs::Transition,
                                   devs::Time) {
  // (the crane's ropes and bodies now) => hook load against the capacity at the outreach
  for (Crane& c : cranes_) {
    if (m.path() != c.check->system) continue;
    double load = 0.0, outreach = 0.0;
    for (const auto& [tension, parts] : c.tensions) load += tension() * parts;
    const double x0 = c.rootX(), y0 = c.rootY();
    for (const auto& [x, y] : c.hoists)
      outreach = std::max(outreach, std::hypot(x() - x0, y() - y0));
    const bool over = load > hookLoadCapacity(c.check->curve, outreach);
    if (over) alarms_.raise(m.path(), c.check->crane, "over_hook_load", true, t, load, !c.over);
    c.over = over;
  }
}

}  // namespace yardsim::run
