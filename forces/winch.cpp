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
  // (t) => last set-point with t_k <= t; binary search, no allocation
  auto it = std::upper_bound(setPoints_.begin(), setPoints_.end(), t,
                             [](double x, const SetPoint& s) { return x < s.t; });
  return it == setPoints_.begin() ? *it : *(it - 1);
}

double Winch::length(double t) const {
  const SetPoint& s = active(t);
  if (s.rate == 0.0) return s.l0;  // also keeps the first set-point (t_k = -inf) finite
  return std::max(minLength_, s.l0 + s.rate * (t - s.t));
}

double Winch::rate(double t) const {
  const SetPoint& s = active(t);
  if (s.rate < 0.0 && s.l0 + s.rate * (t - s.t) <= minLength_) return 0.0;
  return s.rate;
}

void Winch::setPayoutRate(double t, double rate) {
  if (!std::isfinite(t) || !std::isfinite(rate))
    throw std::invalid_argument("winch set-point: time and rate must be finite");
  if (t < setPoints_.back().t)
    throw std::invalid_argument(
        "winch set-point at t = " + std::to_string(t) +
        " s is earlier than the last one at t = " + std::to_string(setPoints_.back().t) + " s");
  setPoints_.push_back({t, length(t), rate});
}

}  // namespace yardsim::forces
