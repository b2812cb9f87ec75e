#pragma once
// A discrete-time (DTSS) model inside the DEVS world. To the coordinator it is a DEVS atomic;
// inside, a continuous state x is advanced on the grid t_k = t0 + k h. Split as adevs splits
// its hybrid model: the model is the system (system.hpp: advance, inputs, event functions,
// time events, outputs, reactions), the stepper (stepper.hpp) places the steps and commits
// them, the one event locator (event_locator.hpp) finds state events; this class only maps the
// DEVS transitions onto them.
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
#include <string>
#include <string_view>
#include <utility>

#include "devs/atomic.hpp"
#include "dtss/state.hpp"
#include "dtss/stepper.hpp"
#include "dtss/system.hpp"

namespace yardsim::dtss {

template <class X>
class Atomic : public devs::Atomic<State<X>>, public System<X> {
 public:
  using S = State<X>;
  // (name, initial state, step h, start time t0, state-event time tolerance)
  Atomic(std::string name, X x0, Time h, Time t0 = 0.0, Time eventTolerance = 1e-9)
      : devs::Atomic<S>(std::move(name), S{x0, t0, x0, t0, Reached{}, 0}),
        stepper_(Grid{t0, h}, eventTolerance) {
    if (!(h > 0.0)) throw devs::ModelError("DTSS model '" + this->name() + "': step h must be > 0");
  }

  Time stepSize() const { return stepper_.grid().h; }
  std::string_view kind() const final { return "dtss"; }

 protected:
  void initialize(Time t0) override { stepper_.lookAhead(*this, this->mutableState(), t0); }

  Time timeAdvance(const S& s) const final { return s.tNext - s.tx; }
  Time nextEventTime(Time /*tl*/) const final { return this->state().tNext; }
  void output(const S& s) const final { this->outputAt(s.xNext, s.tNext, s.reached); }
  void internalTransition(S& s) const final {
    stepper_.commit(*this, s);
    stepper_.lookAhead(*this, s, s.tx);
  }
  void externalTransition(S& s, Time e) const final {
    const Time te = s.tx + e;
    if (te > s.tx) this->advance(s.x, s.tx, te - s.tx);
    s.tx = te;
    this->applyInput(s.x, te);
    stepper_.lookAhead(*this, s, te);
  }
  void confluentTransition(S& s, Time /*e*/) const final {
    stepper_.commit(*this, s);
    this->applyInput(s.x, s.tx);
    stepper_.lookAhead(*this, s, s.tx);
  }

 private:
  Stepper<X> stepper_;
};

}  // namespace yardsim::dtss
