#pragma once
// A discrete-time (DTSS) model inside the DEVS world. To the coordinator it is a DEVS atomic;
// inside, a continuous state x is advanced on the grid t_k = t0 + k h.
//
// Rules (see docs/devs.md):
//  - Look-ahead: after each transition at time t the model computes x at its next target
//    (the next grid point, or an earlier scheduled time event) and schedules itself there.
//    The internal transition commits that state.
//  - External events between steps: an input at t_e < target discards the look-ahead,
//    advances the committed x from its time to t_e exactly (one partial step), applies the
//    input, and continues to the next grid point after t_e: the grid is never shifted.
//    An input exactly at the target is confluent: the step is committed first, then the input.
//  - State events: event functions g_j(x, t) are checked over every advance; when one changes
//    sign the way it is declared to, its crossing time is located (Illinois, to the model's
//    tolerance, by re-advancing from the start of the step), the target is moved there, and an
//    output event is emitted at that time; onStateEvent then lets the model react. Functions
//    that crossed too by the located state are reached at the same time (Reached::coincident).
//  - Time events: times known in advance (nextTimeEvent) are landed on exactly.
#include <algorithm>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "devs/atomic.hpp"
#include "dtss/crossing.hpp"
#include "dtss/grid.hpp"

namespace yardsim::dtss {

// What the look-ahead target of a step is: a grid point, a time event, a located state
// event, or several of them at once (a time event on a grid point).
struct Reached {
  bool grid = false;
  bool timeEvent = false;
  int stateEvent = -1;  // index of the state-event function, -1 when none
  // other state-event functions that crossed the way they are declared to between the start of
  // the step and the located event (within the location tolerance of it): reached at the same
  // time, reported and reacted to with it
  std::vector<int> coincident = {};
  bool operator==(const Reached&) const = default;
};

// The DEVS state of a DTSS model: a plain value type.
template <class X>
struct State {
  X x;                  // committed continuous state
  Time tx = 0.0;        // its time (also the time of the last transition)
  X xNext;              // look-ahead state at tNext
  Time tNext = 0.0;     // next transition time
  Reached reached;      // what tNext is
  std::int64_t steps = 0;  // grid steps committed
};

template <class X>
class Atomic : public devs::Atomic<State<X>> {
 public:
  using S = State<X>;
  // (name, initial state, step h, start time t0, state-event time tolerance)
  Atomic(std::string name, X x0, Time h, Time t0 = 0.0, Time eventTolerance = 1e-9)
      : devs::Atomic<S>(std::move(name), S{x0, t0, x0, t0, Reached{}, 0}),
        grid_{t0, h},
        tolerance_(eventTolerance) {
    if (!(h > 0.0)) throw devs::ModelError("DTSS model '" + this->name() + "': step h must be > 0");
  }

  Time stepSize() const { return grid_.h; }
  std::string_view kind() const final { return "dtss"; }

 protected:
  // (x at t, dt in (0, h]) => x at t + dt
  virtual void advance(X& x, Time t, Time dt) const = 0;
  // (input bags at t) => x after the inputs are applied
  virtual void applyInput(X& /*x*/, Time /*t*/) const {}
  // Directions of the state-event functions; their number is the number of functions.
  virtual std::span<const Crossing> eventDirections() const { return {}; }
  // (x, t) => g_j(x, t) for every state-event function
  virtual void eventFunctions(const X& /*x*/, Time /*t*/, std::span<double> /*g*/) const {}
  // (x, t) => first time event strictly after t (kInfinity when none)
  virtual Time nextTimeEvent(const X& /*x*/, Time /*t*/) const { return devs::kInfinity; }
  // (x at the target, t, what the target is) => output messages at t
  virtual void outputAt(const X& /*x*/, Time /*t*/, const Reached& /*reached*/) const {}
  // (x at a located state event) => x after the model's reaction (bounce, latch, ...)
  virtual void onStateEvent(X& /*x*/, Time /*t*/, int /*event*/) const {}
  // (x at a time event) => x after the model's reaction (a winch stops, a schedule advances)
  virtual void onTimeEvent(X& /*x*/, Time /*t*/) const {}

  void initialize(Time t0) override { lookAhead(this->mutableState(), t0); }

  Time timeAdvance(const S& s) const final { return s.tNext - s.tx; }
  Time nextEventTime(Time /*tl*/) const final { return this->state().tNext; }
  void output(const S& s) const final { outputAt(s.xNext, s.tNext, s.reached); }
  void internalTransition(S& s) const final {
    commit(s);
    lookAhead(s, s.tx);
  }
  void externalTransition(S& s, Time e) const final {
    const Time te = s.tx + e;
    if (te > s.tx) advance(s.x, s.tx, te - s.tx);
    s.tx = te;
    applyInput(s.x, te);
    lookAhead(s, te);
  }
  void confluentTransition(S& s, Time /*e*/) const final {
    commit(s);
    applyInput(s.x, s.tx);
    lookAhead(s, s.tx);
  }

 private:
  // (look-ahead) => committed state, with the state-event reaction applied
  void commit(S& s) const {
    s.x = s.xNext;
    s.tx = s.tNext;
    if (s.reached.grid) ++s.steps;
    if (s.reached.timeEvent) onTimeEvent(s.x, s.tx);
    if (s.reached.stateEvent >= 0) onStateEvent(s.x, s.tx, s.reached.stateEvent);
    for (const int j : s.reached.coincident) onStateEvent(s.x, s.tx, j);
  }

  // (committed x at t) => xNext at the next target, moved to the earliest state event
  void lookAhead(S& s, Time t) const {
    const Time gridTime = grid_.at(grid_.indexAfter(t));
    const Time te = nextTimeEvent(s.x, t);
    const Time target = te > t ? std::min(gridTime, te) : gridTime;
    s.reached = Reached{target == gridTime, target == te, -1};
    s.xNext = s.x;
    advance(s.xNext, t, target - t);
    s.tNext = target;
    const auto dirs = eventDirections();
    if (dirs.empty()) return;
    g0_.resize(dirs.size());
    g1_.resize(dirs.size());
    eventFunctions(s.x, t, g0_);
    eventFunctions(s.xNext, target, g1_);
    Time earliest = devs::kInfinity;
    int which = -1;
    for (std::size_t j = 0; j < dirs.size(); ++j) {
      if (!crosses(g0_[j], g1_[j], dirs[j])) continue;
      X probe = s.x;
      g2_.resize(dirs.size());
      auto g = [&](Time tau) {
        probe = s.x;
        advance(probe, t, tau - t);
        eventFunctions(probe, tau, g2_);
        return g2_[j];
      };
      const Time tc = locateCrossing(g, t, g0_[j], target, g1_[j], tolerance_);
      if (tc < earliest) {
        earliest = tc;
        which = static_cast<int>(j);
      }
    }
    if (which < 0) return;
    if (earliest < target) {
      s.xNext = s.x;
      advance(s.xNext, t, earliest - t);
      s.tNext = earliest;
      s.reached = Reached{};
      eventFunctions(s.xNext, earliest, g1_);
    }
    s.reached.stateEvent = which;
    // (g at the located state) => the others that crossed by then: the same event time
    for (std::size_t j = 0; j < dirs.size(); ++j)
      if (static_cast<int>(j) != which && crosses(g0_[j], g1_[j], dirs[j]))
        s.reached.coincident.push_back(static_cast<int>(j));
  }

  Grid grid_;
  Time tolerance_;
  mutable std::vector<double> g0_, g1_, g2_;  // scratch for event functions
};

}  // namespace yardsim::dtss

namespace yardsim::devs {
// A DTSS state in a checkpoint: the committed and the look-ahead state, their times, what the
// look-ahead reaches and the step count (the model's X needs a StateCodec of its own)
template <class X>
  requires HasStateCodec<X>
struct StateCodec<dtss::State<X>> {
  static void save(CheckpointWriter& w, const dtss::State<X>& s) {
    w.section("dtss");
    devs::save(w, s.x);
    devs::save(w, s.tx);
    devs::save(w, s.xNext);
    devs::save(w, s.tNext);
    devs::save(w, s.reached.grid);
    devs::save(w, s.reached.timeEvent);
    devs::save(w, s.reached.stateEvent);
    devs::save(w, s.reached.coincident);
    devs::save(w, s.steps);
  }
  static void load(CheckpointReader& r, dtss::State<X>& s) {
    r.section("dtss");
    devs::load(r, s.x);
    devs::load(r, s.tx);
    devs::load(r, s.xNext);
    devs::load(r, s.tNext);
    devs::load(r, s.reached.grid);
    devs::load(r, s.reached.timeEvent);
    devs::load(r, s.reached.stateEvent);
    devs::load(r, s.reached.coincident);
    devs::load(r, s.steps);
  }
};

// A DTSS state in a trace: {"t": time of x, "steps": k, "x": x}
template <class X>
struct TraceFormat<dtss::State<X>> {
  static void write(std::string& out, const dtss::State<X>& s) {
    out += "{\"t\":";
    appendJsonNumber(out, s.tx);
    out += ",\"steps\":";
    out += std::to_string(s.steps);
    out += ",\"x\":";
    TraceFormat<X>::write(out, s.x);
    out += '}';
  }
};
}  // namespace yardsim::devs
