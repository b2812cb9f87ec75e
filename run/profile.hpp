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

/// Nanoseconds on steady_clock (a monotonic clock).
std::int64_t steadyNanoseconds();

/// Ticks of the processor's time-stamp counter (x86-64), about three times cheaper to read than
/// steady_clock (a vDSO call); steadyNanoseconds elsewhere.
std::int64_t timeStampTicks();

/// Whether timeStampTicks counts at one rate whatever the core's frequency and sleep states (an
/// invariant time-stamp counter, CPUID 0x80000007 EDX bit 8): what a TimedListener reads then.
bool timeStampTicksInvariant();

/// Forwards every hook to each of `inner` in turn and adds the time they took to `seconds` (the
/// sinks' output time): one pair of clock reads per hook, however many sinks there are, and one
/// pair for a transition's two hooks: the Simulator calls a listener's onState right after its
/// onTransition (devs/listener.hpp), so the clock is read at the transition hook's start and at
/// the state hook's end, and the call from one to the other is all that lies between them. A
/// transition hook that another hook follows instead is closed at that hook's start (counted up
/// to there: more output, never less). The clock is the time-stamp counter where it is invariant
/// (timeStampTicks: a read inside every span costs less), its ticks turned into seconds at every
/// run call's end (onEnd) and when the listener goes, at the rate steady_clock shows over the
/// listener's life; steady_clock's nanoseconds otherwise, booked at once.
class TimedListener final : public devs::Listener {
 public:
  using Clock = std::int64_t (*)();
  /// (sinks, where their seconds go) => the time-stamp counter where it is invariant, else
  /// steady_clock
  TimedListener(std::vector<devs::Listener*> inner, double& seconds)
      : TimedListener(
            timeStampTicksInvariant()
                ? TimedListener(std::move(inner), seconds, timeStampTicks, steadyNanoseconds)
                : TimedListener(std::move(inner), seconds, steadyNanoseconds)) {}
  /// (sinks, seconds, a clock in nanoseconds: tests give one of their own) => booked at once
  TimedListener(std::vector<devs::Listener*> inner, double& seconds, Clock nanoseconds)
      : inner_(std::move(inner)), seconds_(seconds), clock_(nanoseconds) {}
  /// (sinks, seconds, a tick counter, a clock in nanoseconds) => the hooks timed in ticks, booked
  /// in seconds at every run call's end and when the listener goes, at the rate the two clocks
  /// show from the listener's making to then
  TimedListener(std::vector<devs::Listener*> inner, double& seconds, Clock ticks, Clock nanoseconds)
      : inner_(std::move(inner)),
        seconds_(seconds),
        clock_(ticks),
        nanoseconds_(nanoseconds),
        ticks0_(ticks()),
        nanoseconds0_(nanoseconds()) {}
  TimedListener(TimedListener&&) = default;
  ~TimedListener() override { settle(); }
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
    settle();
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
  // (a span's start and end on the clock) => its seconds booked, or its ticks kept for settle()
  void book(std::int64_t start, std::int64_t end) {
    if (nanoseconds_)
      ticks_ += end - start;
    else
      seconds_ += 1e-9 * static_cast<double>(end - start);
  }
  // (ticks kept) => booked in seconds at the rate of ticks to nanoseconds since the making
  void settle() {
    if (!nanoseconds_ || ticks_ == 0) return;
    const auto ticks = static_cast<double>(clock_() - ticks0_);
    const auto nanoseconds = static_cast<double>(nanoseconds_() - nanoseconds0_);
    if (ticks > 0.0) seconds_ += 1e-9 * nanoseconds * (static_cast<double>(ticks_) / ticks);
    ticks_ = 0;
  }
  std::vector<devs::Listener*> inner_;
  double& seconds_;
  Clock clock_;
  Clock nanoseconds_ = nullptr;  // set: clock_ counts ticks, kept in ticks_ until settle()
  std::int64_t ticks0_ = 0, nanoseconds0_ = 0;  // both clocks at the making
  std::int64_t ticks_ = 0;                      // ticks timed, not yet booked
  std::int64_t pairStart_ = 0;
  bool pairOpen_ = false;
};

}  // namespace yardsim::run
