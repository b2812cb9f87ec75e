#pragma once
// Where a run's time goes (`yardsim run --profile`): wall-clock seconds per phase, and a trace
// sink wrapper that books the time spent in a sink's hooks as output.
#include <chrono>
#include <span>
#include <string>
#include <vector>

#include "devs/listener.hpp"

namespace yardsim::run {

/// Wall-clock seconds of each phase of `yardsim run`.
struct PhaseTimes {
  double read = 0.0;        ///< YAML files parsed and the instance tree built
  double validation = 0.0;  ///< mechanical systems, coupling graph, element references, start rules
  double stiffness = 0.0;   ///< the stiffness guard
  double build = 0.0;       ///< the models assembled from the scene
  double simulate = 0.0;    ///< the simulator's set-up and its events, output excluded
  double output = 0.0;  ///< CSV rows, trace records, replay frames, replay.glb, run.json, report
};

/// A running stopwatch: seconds() since construction.
class Stopwatch {
 public:
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

/// (phases) => "profile: read 0.012 s, validation ..., output 0.09 s (17 % of the run), total 0.52
/// s"
std::string formatProfile(const PhaseTimes& p);

/// Forwards every hook to each of `inner` in turn and adds the time they took to `seconds` (the
/// sinks' output time): one pair of clock reads per hook, however many sinks there are.
class TimedListener final : public devs::Listener {
 public:
  TimedListener(std::vector<devs::Listener*> inner, double& seconds)
      : inner_(std::move(inner)), seconds_(seconds) {}
  void onStart(devs::Time t, std::span<devs::AtomicBase* const> a) override {
    timed([&](devs::Listener& l) { l.onStart(t, a); });
  }
  void onOutput(devs::Time t, const devs::AtomicBase& m, const devs::PortBase& p) override {
    timed([&](devs::Listener& l) { l.onOutput(t, m, p); });
  }
  void onInput(devs::Time t, const devs::AtomicBase& m, const devs::PortBase& p) override {
    timed([&](devs::Listener& l) { l.onInput(t, m, p); });
  }
  void onTransition(devs::Time t, const devs::AtomicBase& m, devs::Transition k,
                    devs::Time e) override {
    timed([&](devs::Listener& l) { l.onTransition(t, m, k, e); });
  }
  void onState(devs::Time t, const devs::AtomicBase& m) override {
    timed([&](devs::Listener& l) { l.onState(t, m); });
  }
  void onEnd(devs::Time t) override {
    timed([&](devs::Listener& l) { l.onEnd(t); });
  }

 private:
  template <class F>
  void timed(F&& f) {
    const Stopwatch w;
    for (devs::Listener* l : inner_) f(*l);
    seconds_ += w.seconds();
  }
  std::vector<devs::Listener*> inner_;
  double& seconds_;
};

}  // namespace yardsim::run
