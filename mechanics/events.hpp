#pragma once
// The named event table of a mechanical system: every located state event it can raise, in a
// fixed order (per body: its drive reached its target; per rope: over its minimum breaking load,
// then per rope: slack/taut; per watch: crossed), with the event function whose zero crossing
// the stepper locates. Consumers look an event up by kind, never by index arithmetic.
#include <cstddef>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "dynamics/data.hpp"
#include "mechanics/data.hpp"
#include "mechanics/set_points.hpp"
#include "mechanics/system.hpp"

namespace yardsim::mechanics {

struct EventSlot {
  enum class Kind { None, DriveReached, OverMbl, SlackTaut, WatchCrossed };
  Kind kind = Kind::None;
  int index = 0;          // body (DriveReached), rope (OverMbl, SlackTaut) or watch (WatchCrossed)
  bool bothWays = false;  // false: only rising crossings count
};

// (system) => its events, in the order of the event functions
std::vector<EventSlot> eventTable(const System& s);

// (t, q, v, set-points) => every event function, > 0 past the event (d.scratch holds (q, v)'s
// kinematics afterwards when the system has ropes or watches)
void eventFunctions(const System& s, Data& d, const SetPoints& sp, const Eigen::VectorXd& q,
                    const Eigen::VectorXd& v, double t, std::span<double> g);

// (watch, t, q, v with their kinematics in kin) => the watched quantity in its SI unit
double watched(const System& s, std::size_t w, const dynamics::Data& kin, const Eigen::VectorXd& q,
               const Eigen::VectorXd& v, double t);

}  // namespace yardsim::mechanics
