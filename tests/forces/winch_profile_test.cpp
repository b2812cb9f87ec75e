// The speed profile of a winch drive against its closed forms: the pieces pay out exactly the
// length, start and end at rest, keep speed, acceleration and jerk within the drive's limits, are
// continuous in speed (and in acceleration under a jerk limit), and last L/v + v/a (trapezoid),
// 2 sqrt(L/a) (triangle) or L/v + v/a + a/j (S-curve). And the winch follows the pieces.
#include "forces/winch_profile.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

#include "forces/winch.hpp"

using namespace yardsim::forces;

namespace {

// (piece) => the payout over it, m; its speed and acceleration at its end
double payout(const WinchSegment& p) {
  const double d = p.duration;
  return d * (p.rate + d * (0.5 * p.accel + d * p.jerk / 6.0));
}
double endRate(const WinchSegment& p) {
  return p.rate + p.duration * (p.accel + 0.5 * p.duration * p.jerk);
}
double endAccel(const WinchSegment& p) { return p.accel + p.duration * p.jerk; }

// (profile, amount, drive) => the properties every profile has
void checkProfile(const std::vector<WinchSegment>& ps, double amount, const WinchDrive& d) {
  REQUIRE(!ps.empty());
  double sum = 0.0;
  for (std::size_t k = 0; k < ps.size(); ++k) {
    const WinchSegment& p = ps[k];
    CHECK(p.duration > 0.0);
    sum += payout(p);
    // (within the limits, at both ends of the piece; the speed is monotone within a ramp piece)
    CHECK(std::abs(p.rate) <= d.speed * (1 + 1e-12));
    CHECK(std::abs(endRate(p)) <= d.speed * (1 + 1e-12));
    if (d.accel > 0) {
      CHECK(std::abs(p.accel) <= d.accel * (1 + 1e-12));
      CHECK(std::abs(endAccel(p)) <= d.accel * (1 + 1e-12));
    }
    CHECK(std::abs(p.jerk) <= d.jerk * (1 + 1e-12));
    if (k + 1 < ps.size()) {  // (continuity) => speed, and acceleration under a jerk limit
      CHECK(endRate(p) == Approx(ps[k + 1].rate).margin(1e-12 * d.speed));
      if (d.jerk > 0) CHECK(endAccel(p) == Approx(ps[k + 1].accel).margin(1e-9 * d.accel));
    }
  }
  CHECK(sum == Approx(amount).epsilon(1e-12));
  if (d.accel > 0) {  // (a ramped drive) => from rest to rest
    CHECK(ps.front().rate == 0.0);
    CHECK(endRate(ps.back()) == Approx(0.0).margin(1e-12 * d.speed));
  }
}

}  // namespace

TEST_CASE("an ideal winch runs the whole length at its speed in one piece") {
  const auto ps = winchProfile(-3.9, {0.083});
  REQUIRE(ps.size() == 1);
  CHECK(ps[0].rate == -0.083);
  CHECK(ps[0].duration == 3.9 / 0.083);
  checkProfile(ps, -3.9, {0.083});
}

TEST_CASE("a trapezoid lasts L/v + v/a and a triangle 2 sqrt(L/a)") {
  for (const double amount : {-3.9, 15.8, 0.5}) {
    const WinchDrive d{0.083, 0.02};
    const auto ps = winchProfile(amount, d);
    checkProfile(ps, amount, d);
    const double L = std::abs(amount);
    CHECK(profileDuration(ps) == Approx(L / d.speed + d.speed / d.accel).epsilon(1e-12));
  }
  // (0.1 m is shorter than v^2/a = 0.344 m) => the speed peaks at sqrt(L a) < v
  const WinchDrive d{0.083, 0.02};
  const auto ps = winchProfile(0.1, d);
  checkProfile(ps, 0.1, d);
  CHECK(profileDuration(ps) == Approx(2.0 * std::sqrt(0.1 / d.accel)).epsilon(1e-9));
  double peak = 0.0;
  for (const auto& p : ps) peak = std::max(peak, endRate(p));
  CHECK(peak == Approx(std::sqrt(0.1 * d.accel)).epsilon(1e-9));
}

TEST_CASE("an S-curve lasts L/v + v/a + a/j and keeps every limit") {
  const WinchDrive d{0.083, 0.02, 0.01};  // v j = 8.3e-4 >= a^2 = 4e-4: the acceleration saturates
  for (const double amount : {-3.9, 15.8}) {
    const auto ps = winchProfile(amount, d);
    checkProfile(ps, amount, d);
    CHECK(profileDuration(ps) ==
          Approx(std::abs(amount) / d.speed + d.speed / d.accel + d.accel / d.jerk).epsilon(1e-12));
  }
  // (v j < a^2) => the acceleration peaks at sqrt(v j) < a; each ramp lasts 2 sqrt(v/j)
  const WinchDrive soft{0.083, 0.05, 0.01};
  const auto ps = winchProfile(10.0, soft);
  checkProfile(ps, 10.0, soft);
  CHECK(profileDuration(ps) ==
        Approx(10.0 / soft.speed + 2.0 * std::sqrt(soft.speed / soft.jerk)).epsilon(1e-12));
  // (too short to reach the speed) => still from rest to rest over the exact length
  checkProfile(winchProfile(0.05, d), 0.05, d);
}

TEST_CASE("drives outside their ranges are refused") {
  CHECK_THROWS_AS(winchProfile(1.0, {0.0}), std::invalid_argument);
  CHECK_THROWS_AS(winchProfile(1.0, {0.1, -1.0}), std::invalid_argument);
  CHECK_THROWS_AS(winchProfile(1.0, {0.1, 0.0, 1.0}), std::invalid_argument);  // jerk without accel
  CHECK_THROWS_AS(winchProfile(std::nan(""), {0.1}), std::invalid_argument);
  CHECK_THROWS_AS(winchProfile(1.0, {0.1, INFINITY}), std::invalid_argument);
}

TEST_CASE("the winch follows a profile: continuous length and speed and breaks at the pieces") {
  Winch w(30.0, 1.0);
  const WinchDrive d{0.083, 0.02, 0.01};
  const auto ps = winchProfile(-3.9, d);
  const double tEnd = w.setPayoutProfile(10.0, ps);
  CHECK(tEnd == Approx(10.0 + profileDuration(ps)).epsilon(1e-14));
  CHECK(w.length(10.0) == 30.0);
  CHECK(w.rate(10.0) == 0.0);
  CHECK(w.length(tEnd) == Approx(30.0 - 3.9).epsilon(1e-13));
  CHECK(w.rate(tEnd - 1e-9) == Approx(0.0).margin(1e-9));
  CHECK(w.rate(0.5 * (10.0 + tEnd)) == Approx(-0.083).epsilon(1e-12));  // cruising
  // (the breaks) => every piece's start, then none
  double t = 10.0;
  for (std::size_t k = 1; k < ps.size(); ++k) {
    t += ps[k - 1].duration;
    CHECK(w.nextBreak(t - 1e-6) == Approx(t).epsilon(1e-14));
  }
  CHECK(std::isinf(w.nextBreak(t)));
  // (central differences of L0) => its rate, at a point of every piece
  t = 10.0;
  for (const auto& p : ps) {
    const double tm = t + 0.5 * p.duration, h = 1e-4;
    CHECK((w.length(tm + h) - w.length(tm - h)) / (2 * h) == Approx(w.rate(tm)).margin(1e-8));
    t += p.duration;
  }
}
