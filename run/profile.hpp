#pragma once
// Where a run's time goes (`yardsim run --profile`): wall-clock seconds per phase, and a trace
// sink wrapper that books the time spent in a sink's hooks as output.
#include <chrono>
#include <cstdint>
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

/// Nanoseconds on steady_clock (a monotonic clock): what a TimedListener reads by default.
std::int64_t steadyNanoseconds();

/// Forwards every hook to each of `inner` in turn and adds the time they took to `seconds` (the
/// sinks' output time): one pair of clock reads per hook, however many sinks there are, and one
/// pair for a transition's two hooks: the Simulator calls a listener's onState right after its
/// onTransition (devs/listener.hpp), so the clock is read at the transition hook's start and at
/// the state hook's end, and the call from one to the other is all that lies between them. A
/// transition hook that another hook follows instead is closed at that hook's start (counted up
/// to there: more output, never less). `clock` is for tests (a counter of their own).
class TimedListener final : public devs::Listener {
 public:
  using Clock = std::int64_t (*)();
  TimedListener(std::vector<devs::Listener*> inner, double& seconds,
                Clock clock = steadyNanoseconds)
      : inner_(std::move(inner)), seconds_(seconds), clock_(clock) {}
  void onStart(devs::Time t, std::span<devs::AtomicBase* const> a) override {
    timed([&](devs::Listener& l) { l.onStart(t, a); });
  }
  void onOutput(devs::Time t, const devs::AtomicBase& m, const devs::PortBase& p) override {
    timed([&](devs::Listener& l) { l.onOutput(t, m, p); });
  }
  void onInput(devs::Time t, const devs::AtomicBase& m, const devs::PortBase& p) override {
    timed([&](devs::Listener& l) { l.onInput(t, m, p); });
  }
  // (transition) => the pair's clock started, the hooks forwarded; its state hook stops it
  void onTransition(devs::Time t, const devs::AtomicBase& m, devs::Transition k,
                    devs::Time e) override {
    const std::int64_t start = clock_();
    closePair(start);
    pairStart_ = start;
    pairOpen_ = true;
    for (devs::Listener* l : inner_) l->onTransition(t, m, k, e);
  }
  // (state) => forwarded; timed from its transition hook's start when it follows one
  void onState(devs::Time t, const devs::AtomicBase& m) override {
    const std::int64_t start = pairOpen_ ? pairStart_ : clock_();
    pairOpen_ = false;
    for (devs::Listener* l : inner_) l->onState(t, m);
    book(start, clock_());
  }
  void onEnd(devs::Time t) override {
    timed([&](devs::Listener& l) { l.onEnd(t); });
  }

 private:
  template <class F>
  void timed(F&& f) {
    const std::int64_t start = clock_();
    closePair(start);
    for (devs::Listener* l : inner_) f(*l);
    book(start, clock_());
  }
  // (clock at a hook's start) => a transition hook still open counted up to there
  void closePair(std::int64_t now) {
    if (!pairOpen_) return;
    pairOpen_ = false;
    book(pairStart_, now);
  }
  void book(std::int64_t start, std::int64_t end) {
    seconds_ += 1e-9 * static_cast<double>(end - start);
  }
  std::vector<devs::Listener*> inner_;
  double& seconds_;
  Clock clock_;
  std::int64_t pairStart_ = 0;
  bool pairOpen_ = false;
};

}  // namespace yardsim::run
