#pragma once
// The unstretched length of a rope under a winch: a piecewise polynomial of time set by
// payout-rate set-points at exact times (linear pieces for an ideal winch; quadratic and cubic
// pieces while a drive ramps its speed, forces/winch_profile.hpp), evaluated analytically (no
// integration, no drift) and held at a minimum length while hauling in. Used by every rope.
#include <utility>
#include <vector>

#include "forces/winch_profile.hpp"

namespace yardsim::forces {

class Winch {
 public:
  // (L0 at every time before the first set-point, minimum length) => a winch at rest, m
  Winch(double l0, double minLength);

  // (t, rate) => from time t on, dL0/dt = rate, m/s (> 0 pays out, < 0 hauls in); L0 is
  // continuous at t. Set-points come in time order: throws std::invalid_argument when t is
  // earlier than the last set-point or t, rate are not finite.
  void setPayoutRate(double t, double rate);
  // (t, the pieces of a speed profile) => from time t on, the payout follows the pieces one
  // after the other (the last one's rate holds after them); L0 continuous at every piece's start.
  // Same rules as setPayoutRate. Returns the time the pieces end, s.
  double setPayoutProfile(double t, const std::vector<WinchSegment>& pieces);
  // (t) => set-points planned after t (the rest of a profile) dropped, so that a new request at t
  // replaces the profile under way
  void dropPlannedAfter(double t);
  // (t) => the start of the first piece after t (where L0'' or L0''' jumps), s; inf if none
  double nextBreak(double t) const;
  // (t) => L0(t) = max(minLength, L0(t_k) + rate_k s + accel_k s^2/2 + jerk_k s^3/6), s = t - t_k
  // with t_k the last set-point <= t, m
  double length(double t) const;
  // (t) => dL0/dt at t (0 while held at the minimum length), m/s
  double rate(double t) const;
  double minLength() const { return minLength_; }

  // One piece of L0: from time t on, with s = tau - t,
  // L0(tau) = l0 + rate s + accel s^2 / 2 + jerk s^3 / 6 until the next piece.
  struct SetPoint {
    double t;            // s
    double l0;           // L0(t), m
    double rate;         // m/s
    double accel = 0.0;  // m/s^2
    double jerk = 0.0;   // m/s^3
  };
  // () => every piece so far, in time order (what a checkpoint carries)
  const std::vector<SetPoint>& history() const { return setPoints_; }
  // (pieces of history() of a winch with the same L0 and minimum length) => this winch as it was
  void restoreHistory(std::vector<SetPoint> pieces) { setPoints_ = std::move(pieces); }

 private:
  // (t) => the set-point in force at t (the last one with t_k <= t, else the first)
  const SetPoint& active(double t) const;
  // (t, t >= t_k and finite) => appends the piece starting at t, continuous in L0
  void append(double t, double rate, double accel, double jerk);

  std::vector<SetPoint> setPoints_;
  double minLength_;
};

}  // namespace yardsim::forces
