#pragma once
// The system of a discrete-time model, as adevs splits a hybrid model: what the model itself
// says — how its state advances over a step, how inputs change it, its state-event functions
// and time events, its outputs and its reactions to events. The stepper (stepper.hpp) decides
// where the steps go; the event locator (event_locator.hpp) finds the state events.
#include <span>

#include "devs/time.hpp"
#include "dtss/crossing.hpp"
#include "dtss/state.hpp"

namespace yardsim::dtss {

template <class X>
class System {
 public:
  virtual ~System() = default;
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
};

}  // namespace yardsim::dtss
