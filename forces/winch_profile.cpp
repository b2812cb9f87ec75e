#include "forces/winch_profile.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace yardsim::forces {
namespace {

// (peak speed v, accel limit a, jerk limit j; 0: none) => time to reach v from rest, s
double rampTime(double v, double a, double j) {
  if (a <= 0.0) return 0.0;
  if (j <= 0.0) return v / a;
  if (v * j >= a * a) return v / a + a / j;  // the acceleration saturates at a
  return 2.0 * std::sqrt(v / j);             // a triangle in acceleration, peak sqrt(v j)
}

// (peak speed v, limits) => the length a ramp up and a ramp down cover together, m: each ramp
// is symmetric in acceleration, so it covers v T / 2
double rampsLength(double v, double a, double j) { return v * rampTime(v, a, j); }

// (peak speed v, limits, sign of the payout, +1 rising or -1 falling) => the ramp's pieces
void appendRamp(std::vector<WinchSegment>& out, double v, double a, double j, double sign,
                double dir) {
  const double v0 = dir > 0 ? 0.0 : v;  // speed at the ramp's start
  if (j <= 0.0) {                       // (no jerk limit) => constant acceleration
    out.push_back({v / a, sign * v0, sign * dir * a, 0.0});
    return;
  }
  const double ap = std::min(a, std::sqrt(v * j));  // peak acceleration
  const double tj = ap / j;                          // time to reach it
  const double tc = std::max(0.0, v / ap - tj);      // time at it
  const double dv1 = 0.5 * ap * tj;                  // speed gained while the acceleration rises
  out.push_back({tj, sign * v0, 0.0, sign * dir * j});
  out.push_back({tc, sign * (v0 + dir * dv1), sign * dir * ap, 0.0});
  out.push_back({tj, sign * (v0 + dir * (dv1 + ap * tc)), sign * dir * ap, -sign * dir * j});
}

}  // namespace

std::vector<WinchSegment> winchProfile(double amount, const WinchDrive& d) {
  if (!std::isfinite(amount) || !(d.speed > 0.0) || !std::isfinite(d.speed) || !(d.accel >= 0.0) ||
      !std::isfinite(d.accel) || !(d.jerk >= 0.0) || !std::isfinite(d.jerk) ||
      (d.jerk > 0.0 && d.accel == 0.0))
    throw std::invalid_argument(
        "winch profile: expected a finite length, speed > 0, accel >= 0, jerk >= 0 (jerk only "
        "with accel)");
  const double sign = amount >= 0.0 ? 1.0 : -1.0, length = std::abs(amount);
  std::vector<WinchSegment> out;
  // (no acceleration limit) => one piece at the speed, as an ideal winch
  if (d.accel == 0.0) {
    out.push_back({length / d.speed, sign * d.speed, 0.0, 0.0});
    return out;
  }
  // (length too short for the speed) => the peak speed whose two ramps cover the length
  // (rampsLength grows monotonically with v: bisection)
  double v = d.speed;
  if (rampsLength(v, d.accel, d.jerk) > length) {
    double lo = 0.0, hi = v;
    for (int i = 0; i < 200 && hi - lo > 1e-15 * d.speed; ++i) {
      const double mid = 0.5 * (lo + hi);
      (rampsLength(mid, d.accel, d.jerk) > length ? hi : lo) = mid;
    }
    v = lo;
  }
  const double cruise = (length - rampsLength(v, d.accel, d.jerk)) / v;
  appendRamp(out, v, d.accel, d.jerk, sign, +1.0);
  out.push_back({std::max(0.0, cruise), sign * v, 0.0, 0.0});
  appendRamp(out, v, d.accel, d.jerk, sign, -1.0);
  std::erase_if(out, [](const WinchSegment& s) { return !(s.duration > 0.0); });
  return out;
}

double profileDuration(const std::vector<WinchSegment>& pieces) {
  double t = 0.0;
  for (const auto& p : pieces) t += p.duration;
  return t;
}

}  // namespace yardsim::forces
