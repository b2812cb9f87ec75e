#include "forces/winch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace yardsim::forces {

Winch::Winch(double l0, double minLength) : minLength_(minLength) {
  setPoints_.push_back({-std::numeric_limits<double>::infinity(), l0, 0.0});
}

const Winch::SetPoint& Winch::active(double t) const {
  // (t) => last set-point with t_k <= t; the last one at once (where a run's time usually is),
  // else a binary search; no allocation
  if (t >= setPoints_.back().t) return setPoints_.back();
  auto it = std::upper_bound(setPoints_.begin(), setPoints_.end(), t,
                             [](double x, const SetPoint& s) { return x < s.t; });
  return it == setPoints_.begin() ? *it : *(it - 1);
}

namespace {
// (piece, t) => the unclamped L0 and dL0/dt of the piece at t
double pieceLength(const Winch::SetPoint& s, double t) {
  const double u = t - s.t;
  if (s.accel == 0.0 && s.jerk == 0.0) return s.l0 + s.rate * u;  // a linear piece, exactly
  return s.l0 + u * (s.rate + u * (0.5 * s.accel + u * s.jerk / 6.0));
}
double pieceRate(const Winch::SetPoint& s, double t) {
  const double u = t - s.t;
  return s.rate + u * (s.accel + 0.5 * u * s.jerk);
}
bool moving(const Winch::SetPoint& s) { return s.rate != 0.0 || s.accel != 0.0 || s.jerk != 0.0; }
}  // namespace

double Winch::length(double t) const {
  const SetPoint& s = active(t);
  if (!moving(s)) return s.l0;  // also keeps the first set-point (t_k = -inf) finite
  return std::max(minLength_, pieceLength(s, t));
}

double Winch::rate(double t) const {
  const SetPoint& s = active(t);
  if (!moving(s)) return 0.0;
  const double r = pieceRate(s, t);
  if (r < 0.0 && pieceLength(s, t) <= minLength_) return 0.0;
  return r;
}

void Winch::append(double t, double rate, double accel, double jerk) {
  if (!std::isfinite(t) || !std::isfinite(rate) || !std::isfinite(accel) || !std::isfinite(jerk))
    throw std::invalid_argument("winch set-point: time and rate must be finite");
  if (t < setPoints_.back().t)
    throw std::invalid_argument(
        "winch set-point at t = " + std::to_string(t) +
        " s is earlier than the last one at t = " + std::to_string(setPoints_.back().t) + " s");
  setPoints_.push_back({t, length(t), rate, accel, jerk});
}

void Winch::setPayoutRate(double t, double rate) { append(t, rate, 0.0, 0.0); }

double Winch::setPayoutProfile(double t, const std::vector<WinchSegment>& pieces) {
  for (const WinchSegment& p : pieces) {
    append(t, p.rate, p.accel, p.jerk);
    t += p.duration;
  }
  return t;
}

void Winch::dropPlannedAfter(double t) {
  while (setPoints_.size() > 1 && setPoints_.back().t > t) setPoints_.pop_back();
}

double Winch::nextBreak(double t) const {
  auto it = std::upper_bound(setPoints_.begin(), setPoints_.end(), t,
                             [](double x, const SetPoint& s) { return x < s.t; });
  return it == setPoints_.end() ? std::numeric_limits<double>::infinity() : it->t;
}

}  // namespace yardsim::forces
