#pragma once
// A crane's hook-load curve checked during the run (docs/database.md, "Hook-load alarm"): after
// every transition of the multibody model that holds a crane's hoist ropes, the hook load (the
// sum of tension x parts over its hoist ropes, N) is compared with the capacity of its curve at
// the current outreach (the largest horizontal distance from its root body to a body a hoist
// rope hangs from, m; linear between the curve's points, the first point's capacity below it,
// 0 beyond its last point: the crane is not rated there). Each time the load goes above the
// capacity is one `over_hook_load` alarm of the AlarmMonitor (element: the crane's path; value:
// the hook load, the worst kept while it stays above), shown and counted like over_mbl. The
// values are read through the models' channels; nothing is recorded or traced.
#include <functional>
#include <string>
#include <vector>

#include "devs/listener.hpp"
#include "models/channels.hpp"
#include "run/alarms.hpp"
#include "scene/scene.hpp"

namespace yardsim::run {

// (curve: (outreach m, capacity N) ascending, outreach m) => the capacity there, N
double hookLoadCapacity(const std::vector<std::pair<double, double>>& curve, double outreach);

class HookLoadMonitor final : public devs::Listener {
 public:
  // (the scene's checks, every channel of the assembled root, the alarms to raise into) =>
  // the monitor; std::invalid_argument naming a channel that is missing (an internal fault)
  HookLoadMonitor(const std::vector<scene::HookLoadCheck>& checks,
                  const std::vector<models::Channel>& channels, AlarmMonitor& alarms);
  void onTransition(devs::Time t, const devs::AtomicBase& m, devs::Transition kind,
                    devs::Time e) override;
  bool empty() const { return cranes_.empty(); }

 private:
  struct Crane {
    const scene::HookLoadCheck* check;
    std::vector<std::pair<std::function<double()>, int>> tensions;  // per part, N; parts
    std::function<double()> rootX, rootY;                           // m, world
    std::vector<std::pair<std::function<double()>, std::function<double()>>> hoists;  // x, y
    bool over = false;
  };
  std::vector<Crane> cranes_;
  AlarmMonitor& alarms_;
};

}  // namespace yardsim::run
