#pragma once
// Safety events made visible (docs/scenes.md, "Alarms"): a listener on every multibody model's
// `event` port that keeps, per element and kind, the first time, the count and the worst value:
// a rope over its minimum breaking load (over_mbl), a watched quantity past its threshold
// (crossed) and a crane's hook load over its curve (over_hook_load, run/hook_load_monitor.hpp)
// are alarms; a rope going slack or taut is a notice; a warning the run printed (the stiffness
// guard's, any warning of the scene's validation) is one `warning` each, raised at the start.
// The runner calls back at each first occurrence (the console line) and writes the list into
// run.json.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "devs/listener.hpp"
#include "devs/model.hpp"
#include "models/diagnostics.hpp"

namespace yardsim::run {

struct Alarm {
  std::string model;     // the multibody model's path
  std::string element;   // rope or watch name
  std::string kind;      // over_mbl, crossed, over_hook_load, slack, taut, warning
  std::string severity;  // alarm (over_mbl, crossed, over_hook_load), notice (slack, taut) or
                         // warning (warning)
  double first = 0.0;    // s: the first occurrence, as located
  std::size_t count = 0;
  double worst = 0.0;    // SI: the largest value reported (for over_mbl the rope's peak tension
                         // in N, raiseToRopePeaks; hook load in N for over_hook_load; for crossed
                         // the watched quantity's extreme beyond its threshold, WatchExtremes;
                         // for a warning its value, omega_max dt for the stiffness guard, or NaN)
  double worstAt = 0.0;  // s: when the worst value was reached
  std::string message = {};  // a warning's text (file:line:col: key path: message); "" otherwise
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
  // (a warning of the scene's validation, the run's start time, whether it counts as a new
  // occurrence) => one `warning` per distinct (model, element, message): the stiffness guard's
  // names its system, the stiffest body and omega_max dt; another names its key path
  void warn(const models::Diagnostic& d, double t, bool occurrence = true);
  // (model path, element, kind, whether larger is worse, time, value) => a known alarm's worst
  // value and its time moved to `value` when that is worse; an unknown one is left alone
  void worsen(const std::string& model, const std::string& element, const std::string& kind,
              bool larger, double t, double value);
  // every (element, kind) seen, in order of first occurrence
  const std::vector<Alarm>& alarms() const { return alarms_; }
  // (alarms of the run a checkpoint was taken in) => counted on from there (restarts)
  void restore(std::vector<Alarm> alarms) { alarms_ = std::move(alarms); }
  // the number of distinct alarms of severity "alarm"
  std::size_t alarmCount() const;
  // the number of distinct warnings (severity "warning")
  std::size_t warningCount() const;

 private:
  // (key, message) => the alarm of that key, or nullptr
  Alarm* find(const std::string& model, const std::string& element, const std::string& kind,
              const std::string& message = {});
  std::function<void(const Alarm&)> onFirst_;
  std::vector<Alarm> alarms_;
};

}  // namespace yardsim::run
