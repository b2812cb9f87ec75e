#pragma once
// The named event table of a mechanical system: every located state event it can raise, in a
// fixed order (per body: its drive reached its target; per rope: over its minimum breaking load,
// then per rope: slack/taut; per watch: crossed; per event a provider declares: its own), with the
// event function whose zero crossing the stepper locates. Consumers look an event up by kind, never
// by index arithmetic.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dynamics/data.hpp"
#include "mechanics/data.hpp"
#include "mechanics/set_points.hpp"
#include "mechanics/system.hpp"

namespace yardsim::mechanics {

struct EventSlot {
  enum class Kind { None, DriveReached, OverMbl, SlackTaut, WatchCrossed, Provider };
  Kind kind = Kind::None;
  int index = 0;          // body (DriveReached), rope (OverMbl, SlackTaut), watch (WatchCrossed) or
                          // provider event (Provider, System::providerEvents())
  bool bothWays = false;  // false: only rising crossings count
};

// What an event says: the element (joint, rope, watch), the actor that asked for it ("" for
// none), its kind (reached, done, over_mbl, taut, slack, crossed) and the quantity then (SI).
struct EventReport {
  std::string element, actor, kind;
  double value = 0.0;
  std::string detail = {};  // provider events: the pair, witness points ("" for none)
};

// (system) => its events, in the order of the event functions
std::vector<EventSlot> eventTable(const System& s);

// (t, q, v, set-points) => every event function, > 0 past the event (d.scratch holds (q, v)'s
// kinematics afterwards when the system has ropes or watches)
void eventFunctions(const System& s, Data& d, const SetPoints& sp, const Eigen::VectorXd& q,
                    const Eigen::VectorXd& v, double t, std::span<double> g);

// (the located state event that fired at t, state then) => its report
EventReport reportStateEvent(const System& s, Data& d, const SetPoints& sp,
                             const Eigen::VectorXd& q, const Eigen::VectorXd& v, double t,
                             const EventSlot& e);

// (set-points, t) => the reports of the time events due at t: winch jobs done, prescribed ramps
// at their targets
void reportTimeEvents(const System& s, const SetPoints& sp, const Eigen::VectorXd& q, double t,
                      std::vector<EventReport>& out);

// (set-points, t) => the next time event after t, s (a winch job's or a prescribed ramp's end,
// a kink or jump of a body load's time series), or infinity
double nextTimeEvent(const System& s, const SetPoints& sp, double t);

// (watch, t, q, v with their kinematics in kin) => the watched quantity in its SI unit
double watched(const System& s, std::size_t w, const dynamics::Data& kin, const Eigen::VectorXd& q,
               const Eigen::VectorXd& v, double t);

}  // namespace yardsim::mechanics
