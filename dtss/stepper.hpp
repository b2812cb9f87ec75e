#pragma once
// The stepper of discrete-time models: where the steps go. From the committed state at t it
// takes the next target — the next grid point t_k = t0 + k h, or an earlier time event — as the
// look-ahead, has the event locator move it to the earliest state event in between, and at the
// target commits it with the model's reactions to what was reached. The grid is never shifted.
#include <algorithm>
#include <utility>

#include "dtss/event_locator.hpp"
#include "dtss/grid.hpp"
#include "dtss/state.hpp"
#include "dtss/system.hpp"

namespace yardsim::dtss {

template <class X>
class Stepper {
 public:
  // (grid, state-event tolerance) => a stepper
  Stepper(Grid grid, Time eventTolerance) : grid_(grid), locator_(eventTolerance) {}
  const Grid& grid() const { return grid_; }

  // (committed s.x at t) => s.xNext at the next target, moved to the earliest state event
  void lookAhead(const System<X>& sys, State<X>& s, Time t) const {
    const Time gridTime = grid_.at(grid_.indexAfter(t));
    const Time te = sys.nextTimeEvent(s.x, t);
    const Time target = te > t ? std::min(gridTime, te) : gridTime;
    s.reached = Reached{target == gridTime, target == te, -1};
    s.xNext = s.x;
    sys.advance(s.xNext, t, target - t);
    s.tNext = target;
    locator_.locate(sys, s, t);
  }

  // (look-ahead) => committed state, with the reactions to what it reached applied; the look-ahead
  // is swapped in, not copied: s.xNext holds the old state until the lookAhead that always follows
  // a commit (atomic.hpp) sets it again, and nothing reads it in between
  void commit(const System<X>& sys, State<X>& s) const {
    using std::swap;
    swap(s.x, s.xNext);
    s.tx = s.tNext;
    if (s.reached.grid) ++s.steps;
    if (s.reached.timeEvent) sys.onTimeEvent(s.x, s.tx);
    if (s.reached.stateEvent >= 0) sys.onStateEvent(s.x, s.tx, s.reached.stateEvent);
    for (const int j : s.reached.coincident) sys.onStateEvent(s.x, s.tx, j);
  }

 private:
  Grid grid_;
  EventLocator<X> locator_;
};

}  // namespace yardsim::dtss
