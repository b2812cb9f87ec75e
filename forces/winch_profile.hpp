#pragma once
// The speed profile of a winch drive paying out (or hauling in) a length: the speed rises to the
// drive's speed with a bounded acceleration (a trapezoid in speed) and, when a jerk limit is
// given, with a bounded rate of change of acceleration (an S-curve), cruises, and comes down the
// same way, so that it stops exactly after the length. When the length is too short to reach
// the speed, the profile peaks at the highest speed that still stops in time. Without an
// acceleration limit the speed steps at once (the drive of an ideal winch).
// Units: m, m/s, m/s^2, m/s^3, s; rates signed as the payout (> 0 pays out, < 0 hauls in).
#include <vector>

namespace yardsim::forces {

// One piece of the profile: for `duration` s from its start, the payout rate is
// rate + accel s + jerk s^2 / 2 (s: time since the piece's start).
struct WinchSegment {
  double duration = 0.0;  // s
  double rate = 0.0;      // m/s at the start of the piece
  double accel = 0.0;     // m/s^2 at the start of the piece
  double jerk = 0.0;      // m/s^3 over the piece
};

struct WinchDrive {
  double speed = 0.0;  // m/s, > 0
  double accel = 0.0;  // m/s^2, >= 0; 0: no limit (the speed steps)
  double jerk = 0.0;   // m/s^3, >= 0; 0: no limit (a trapezoid); needs accel > 0
};

// (signed length, m; the drive) => the pieces in time order, whose payout sums to the length;
// pieces of zero duration are left out. Throws std::invalid_argument for a non-finite length or
// a drive outside the ranges above.
std::vector<WinchSegment> winchProfile(double amount, const WinchDrive& drive);

// (the pieces) => their total duration, s
double profileDuration(const std::vector<WinchSegment>& pieces);

}  // namespace yardsim::forces
