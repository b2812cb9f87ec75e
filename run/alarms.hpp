#pragma once
// Safety events made visible (docs/scenes.md, "Alarms"): a listener on every multibody model's
// `event` port that keeps, per element and kind, the first time, the count and the worst value:
// a rope over its minimum breaking load (over_mbl), a watched quantity past its threshold
// (crossed) and a crane's hook load over its curve (over_hook_load, run/hook_load_monitor.hpp)
// are alarms; a rope going slack or taut is a notice. The runner calls back at each
// first occurrence (the console line) and writes the list into run.json.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "devs/listener.hpp"
#include "devs/model.hpp"

namespace yardsim::run {

struct Alarm {
  std::string model;     // the multibody model's path
  std::string element;   // rope or watch name
  std::string kind;      // over_mbl, crossed, over_hook_load, slack, taut
  std::string severity;  // alarm (over_mbl, crossed, over_hook_load) or notice (slack, taut)
  double first = 0.0;    // s: the first occurrence, as located
  std::size_t count = 0;
  double worst = 0.0;  // SI: the largest value reported (for over_mbl the rope's peak tension
                       // in N, raiseToRopePeaks; hook load in N for over_hook_load)
};

// (alarms, the model tree at the end of the run) => every over_mbl alarm's worst value is its
// rope's peak tension over every step (the event is located where the tension crosses the MBL,
// so its own value is the MBL; the peak comes after, between events)
void raiseToRopePeaks(std::vector<Alarm>& alarms, const devs::Model& root);

class AlarmMonitor final : public devs::Listener {
 public:
  // (alarm at its first occurrence) => e.g. a console line; may be empty
  explicit AlarmMonitor(std::function<void(const Alarm&)> onFirst = {})
      : onFirst_(std::move(onFirst)) {}
  void onOutput(devs::Time t, const devs::AtomicBase& m, const devs::PortBase& port) override;
  // (model path, element, kind, whether an alarm or a notice, time, value, whether a new
  // occurrence or the same one going on) => a new (model, element, kind) reported through
  // onFirst, a known one counted (a new occurrence) and its worst value kept
  void raise(const std::string& model, const std::string& element, const std::string& kind,
             bool alarm, double t, double value, bool occurrence = true);
  // every (element, kind) seen, in order of first occurrence
  const std::vector<Alarm>& alarms() const { return alarms_; }
  // (alarms of the run a checkpoint was taken in) => counted on from there (restarts)
  void restore(std::vector<Alarm> alarms) { alarms_ = std::move(alarms); }
  // the number of distinct alarms of severity "alarm"
  std::size_t alarmCount() const;

 private:
  std::function<void(const Alarm&)> onFirst_;
  std::vector<Alarm> alarms_;
};

}  // namespace yardsim::run
