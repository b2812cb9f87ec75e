#pragma once
// The Parallel DEVS root coordinator over a flattened model.
//
// One event time (step):
//  1. every imminent atomic (tn == t) runs its output function;
//  2. each output bag is copied to the input ports it reaches (flattened couplings);
//  3. imminent atomics with input run deltaConf, imminent ones without run deltaInt,
//     non-imminent receivers run deltaExt(e = t - tl);
//  4. bags are cleared, and every atomic that transitioned is rescheduled (tn = t + ta).
// Tie rule: all atomics imminent at the same t act together (no select function); outputs
// are computed from the states before any transition of that t, and zero time advances make
// further event times at the same t, processed by the next step in order.
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

#include "devs/event_queue.hpp"
#include "devs/flatten.hpp"
#include "devs/listener.hpp"

namespace yardsim::devs {

// A model broke the rules at run time (negative or NaN time advance).
class SimulationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct SimulatorStats {
  std::uint64_t eventTimes = 0;  // steps that executed at least one transition
  std::uint64_t internal = 0;
  std::uint64_t external = 0;
  std::uint64_t confluent = 0;
  std::uint64_t messages = 0;  // messages delivered to input ports
};

class Simulator {
 public:
  // (root model, start time) => flattened, every atomic initialised and scheduled
  explicit Simulator(Model& root, Time t0 = 0.0);

  // (listener) => receives every hook from now on; not owned, must outlive the run
  void addListener(Listener& listener);

  Time time() const { return t_; }
  Time nextEventTime() const { return queue_.topTime(); }
  // () => all events of the next event time executed; false when no event is left
  bool step();
  // (t_end) => every event with t <= t_end executed; time() == t_end afterwards
  void runUntil(Time tEnd);
  // () => run until no event is left
  void run() { runUntil(kInfinity); }

  const SimulatorStats& stats() const { return stats_; }
  // (n > 0) => a run that executes more than n transitions at one simulated time stops with a
  // SimulationError naming the models of the last step (an illegitimate model that never lets
  // time advance would otherwise loop forever, writing its trace); 0 (default): no limit
  void setInstantLimit(std::uint64_t n) { instantLimit_ = n; }
  std::span<AtomicBase* const> atomics() const { return flat_.atomics; }

  // Checkpoints (between event times only: after step() or runUntil() returned).
  // () => the first model whose state cannot be archived, or nullptr when all can
  const AtomicBase* firstUncheckpointable() const;
  // (archive) => the clock, the event queue, the counters and every atomic's state appended;
  // then each atomic's afterCheckpoint() (what it could not archive restarts here)
  void saveCheckpoint(CheckpointWriter& w);
  // (archive written by saveCheckpoint for the same model) => the run continues from there;
  // listeners get onStart but no initial state records (the trace goes on where it stopped).
  // Throws CheckpointError when the models differ (count or paths) or the archive is broken.
  void loadCheckpoint(CheckpointReader& r);

 private:
  void start();  // start hooks, once
  void reschedule(std::uint32_t i, Time t);
  // (atomic after its transition) => its input bags empty
  static void clearInputs(AtomicBase& a);
  void notifyEnd();

  // What a transition reads of atomic i, side by side: one cache line's share per atomic
  // instead of one line in each of three lists (the imminent atomics come in heap order)
  struct Slot {
    AtomicBase* model;
    Time tl;                          // time of the last transition
    std::uint32_t outFirst, outLast;  // its output ports: flat_.outs[outFirst, outLast)
  };

  FlatModel flat_;
  EventQueue queue_;
  // Per-atomic lists, sized once in the model arena (devs/model_arena.hpp) beside flat_'s
  ListVector<Slot> slots_;
  ListVector<std::uint8_t> flags_;       // kImminent | kHasInput per atomic
  ListVector<std::uint32_t> imminent_;   // scratch, reused every step
  ListVector<std::uint32_t> receivers_;  // non-imminent atomics that got input
  std::vector<PortBase*> filled_;        // traced runs: input ports filled this step
  std::vector<Listener*> listeners_;
  SimulatorStats stats_;
  Time t_;
  bool started_ = false;
  std::uint64_t instantLimit_ = 0;
  std::uint64_t atInstant_ = 0;  // transitions executed at time lastInstant_ so far
  Time lastInstant_ = -kInfinity;
  // (t, transitions of this step) => counted; throws past the limit
  void countInstant(Time t, std::size_t transitions);
};

}  // namespace yardsim::devs
