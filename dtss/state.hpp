#pragma once
// The DEVS state of a discrete-time model (a plain value: the committed state, the look-ahead
// state and what it reaches), how it goes into a trace and into a checkpoint.
#include <cstdint>
#include <string>
#include <tuple>
#include <vector>

#include "devs/checkpoint_archive.hpp"
#include "devs/time.hpp"
#include "devs/trace_format.hpp"
#include "devs/trace_state_head.hpp"

namespace yardsim::dtss {

using devs::Time;

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
  X x;                     // committed continuous state
  Time tx = 0.0;           // its time (also the time of the last transition)
  X xNext;                 // look-ahead state at tNext
  Time tNext = 0.0;        // next transition time
  Reached reached;         // what tNext is
  std::int64_t steps = 0;  // grid steps committed
};

}  // namespace yardsim::dtss

namespace yardsim::devs {
// A DTSS state in a checkpoint: the committed and the look-ahead state, their times, what the
// look-ahead reaches and the step count (the model's X needs a StateCodec of its own)
template <class X>
requires HasStateCodec<X>
struct StateCodec<dtss::State<X>> : FieldCodec<dtss::State<X>> {
  static auto fields(auto& s) {
    return std::tie(s.x, s.tx, s.xNext, s.tNext, s.reached.grid, s.reached.timeEvent,
                    s.reached.stateEvent, s.reached.coincident, s.steps);
  }
};

// A DTSS state in a trace: {"t": time of x, "steps": k, "x": x}, its head in one append
template <class X>
struct TraceFormat<dtss::State<X>> {
  static void write(std::string& out, const dtss::State<X>& s) {
    appendStateHead(out, s.tx, static_cast<std::uint64_t>(s.steps));  // steps: counted up from 0
    TraceFormat<X>::write(out, s.x);
    out += '}';
  }
};
}  // namespace yardsim::devs
