#pragma once
// The unstretched length of a rope under a winch: a piecewise-linear function of time set by
// payout-rate set-points at exact times, evaluated analytically (no integration, no drift) and
// held at a minimum length while hauling in. Used by the wire rope and the equalizer.
#include <utility>
#include <vector>

namespace yardsim::forces {

class Winch {
 public:
  // (L0 at every time before the first set-point, minimum length) => a winch at rest, m
  Winch(double l0, double minLength);

  // (t, rate) => from time t on, dL0/dt = rate, m/s (> 0 pays out, < 0 hauls in); L0 is
  // continuous at t. Set-points come in time order: throws std::invalid_argument when t is
  // earlier than the last set-point or t, rate are not finite.
  void setPayoutRate(double t, double rate);
  // (t) => L0(t) = max(minLength, L0(t_k) + rate_k (t - t_k)) with t_k the last set-point <= t, m
  double length(double t) const;
  // (t) => dL0/dt at t (0 while held at the minimum length), m/s
  double rate(double t) const;
  double minLength() const { return minLength_; }

  // One piece of L0: from time t on, L0(tau) = l0 + rate (tau - t) until the next piece.
  struct SetPoint {
    double t;     // s
    double l0;    // L0(t), m
    double rate;  // m/s
  };
  // () => every piece so far, in time order (what a checkpoint carries)
  const std::vector<SetPoint>& history() const { return setPoints_; }
  // (pieces of history() of a winch with the same L0 and minimum length) => this winch as it was
  void restoreHistory(std::vector<SetPoint> pieces) { setPoints_ = std::move(pieces); }

 private:
  // (t) => the set-point in force at t (the last one with t_k <= t, else the first)
  const SetPoint& active(double t) const;

  std::vector<SetPoint> setPoints_;
  double minLength_;
};

}  // namespace yardsim::forces
