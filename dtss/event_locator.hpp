#pragma once
// The one event locator of discrete-time models: after the stepper advanced the committed state
// x at t to the look-ahead xNext at the target, it checks every state-event function for a
// crossing in its declared direction, locates the earliest one (Illinois, crossing.hpp, to the
// model's tolerance, by re-advancing from x, so no interpolant is needed), moves the look-ahead
// there, and lists the functions that crossed by then too (Reached::coincident).
#include <algorithm>
#include <vector>

#include "dtss/crossing.hpp"
#include "dtss/state.hpp"
#include "dtss/system.hpp"

namespace yardsim::dtss {

template <class X>
class EventLocator {
 public:
  explicit EventLocator(Time tolerance) : tolerance_(tolerance) {}
  Time tolerance() const { return tolerance_; }

  // (system, s.x at t, s.xNext at the target s.tNext) => s.xNext, s.tNext and s.reached moved to
  // the earliest state event in the step, if any
  void locate(const System<X>& sys, State<X>& s, Time t) const {
    const auto dirs = sys.eventDirections();
    if (dirs.empty()) return;
    const Time target = s.tNext;
    g0_.resize(dirs.size());
    g1_.resize(dirs.size());
    sys.eventFunctions(s.x, t, g0_);
    sys.eventFunctions(s.xNext, target, g1_);
    Time earliest = devs::kInfinity;
    int which = -1;
    for (std::size_t j = 0; j < dirs.size(); ++j) {
      if (!crosses(g0_[j], g1_[j], dirs[j])) continue;
      X probe = s.x;
      g2_.resize(dirs.size());
      auto g = [&](Time tau) {
        probe = s.x;
        sys.advance(probe, t, tau - t);
        sys.eventFunctions(probe, tau, g2_);
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
      sys.advance(s.xNext, t, earliest - t);
      s.tNext = earliest;
      s.reached = Reached{};
      sys.eventFunctions(s.xNext, earliest, g1_);
    }
    s.reached.stateEvent = which;
    // (g at the located state) => the others that crossed by then: the same event time
    for (std::size_t j = 0; j < dirs.size(); ++j)
      if (static_cast<int>(j) != which && crosses(g0_[j], g1_[j], dirs[j]))
        s.reached.coincident.push_back(static_cast<int>(j));
  }

 private:
  Time tolerance_;
  mutable std::vector<double> g0_, g1_, g2_;  // scratch for event functions
};

}  // namespace yardsim::dtss
