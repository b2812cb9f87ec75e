#pragma once
// Observer hooks of the Simulator: the trace sink interface. Models never log; whatever is
// traced is seen here. With no listener attached the Simulator skips every hook.
#include <span>

#include "devs/atomic.hpp"
#include "devs/time.hpp"

namespace yardsim::devs {

class Listener {
 public:
  virtual ~Listener() = default;
  // (start time, every atomic in flat order) => before the first event
  virtual void onStart(Time /*t*/, std::span<AtomicBase* const> /*atomics*/) {}
  // (t, model, output port holding this event time's bag) => after the model's output function
  virtual void onOutput(Time /*t*/, const AtomicBase& /*m*/, const PortBase& /*port*/) {}
  // (t, model, input port holding the delivered bag) => before the model's transition
  virtual void onInput(Time /*t*/, const AtomicBase& /*m*/, const PortBase& /*port*/) {}
  // (t, model, which transition, elapsed time e since the previous one) => after it ran
  virtual void onTransition(Time /*t*/, const AtomicBase& /*m*/, Transition /*kind*/,
                            Time /*e*/) {}
  // (t, model) => its state after a transition (and at start); after a transition the Simulator
  // calls it on each listener right after that listener's onTransition, nothing in between
  virtual void onState(Time /*t*/, const AtomicBase& /*m*/) {}
  // (t) => when a run call returns
  virtual void onEnd(Time /*t*/) {}
};

}  // namespace yardsim::devs
