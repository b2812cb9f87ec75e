// Set-point dispatch against its definitions: a prescribed ramp starts at the ramp's speed (the
// velocity step is the ramp speed minus the joint's velocity, towards the target), a ramp to
// where the joint already is stops it, a servo drive takes no impulse; a winch job ends after
// |amount| / speed and pays out (> 0) or hauls in (< 0). Random cases, both directions.
#include "mechanics/set_points.hpp"

#include <catch2/catch.hpp>

#include <limits>
#include <random>

using namespace yardsim::mechanics;

TEST_CASE(
    "startDrive: the velocity step of a prescribed ramp, none for a servo, a stop at the target") {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int trial = 0; trial < 200; ++trial) {
    SetPoints sp{std::vector<JointDrive>(3), {}, {}};
    const double q = u(rng), v = u(rng), target = u(rng), speed = 0.1 + std::abs(u(rng)),
                 t = std::abs(u(rng));
    const double up = target >= q ? 1.0 : -1.0;
    CHECK(startDrive(sp, 2, q, v, target, speed, t, "a", true) ==
          Approx(up * speed - v).margin(1e-15));
    const JointDrive& d = sp.drives[2];
    CHECK(d.active);
    CHECK_FALSE(d.reported);
    CHECK(d.prescribed);
    CHECK(d.start == q);
    CHECK(d.target == target);
    CHECK(d.t0 == t);
    CHECK(d.tEnd() == Approx(t + std::abs(target - q) / speed));
    CHECK(startDrive(sp, 2, q, v, target, -speed, t, "a", false) ==
          0.0);                                                    // a servo keeps its velocity
    CHECK(sp.drives[2].speed == speed);                            // |speed|
    CHECK(startDrive(sp, 1, q, v, q, speed, t, "a", true) == -v);  // already there: stop
  }
}

TEST_CASE(
    "startWinch: the job ends after |amount| / speed and pays out positive and hauls in negative") {
  SetPoints sp{{}, {}, std::vector<WinchJob>(2)};
  yardsim::forces::Winch w1(20.0, 1.0), w0(20.0, 1.0);
  CHECK(startWinch(sp, 1, w1, 10.0, 2.0, {0.5}, "w") == Approx(14.0));
  CHECK(sp.winches[1].tEnd == Approx(14.0));
  CHECK(sp.winches[1].actor == "w");
  CHECK(w1.rate(12.0) == 0.5);
  CHECK(sp.winches[1].pieces.size() == w1.history().size());  // (state) mirrors the winch
  CHECK(startWinch(sp, 0, w0, 3.0, -1.0, {0.25}, "h") == Approx(7.0));
  CHECK(w0.rate(5.0) == -0.25);
  CHECK(sp.winches[0].active);
}

TEST_CASE("startWinch: a new request replaces the rest of a ramped profile under way") {
  SetPoints sp{{}, {}, std::vector<WinchJob>(1)};
  yardsim::forces::Winch w(20.0, 1.0);
  // (10 m at 1 m/s, 0.5 m/s^2) => ramps of 2 s, ends at 12 s
  CHECK(startWinch(sp, 0, w, 0.0, 10.0, {1.0, 0.5}, "a") == Approx(12.0));
  CHECK(w.nextBreak(1.0) == Approx(2.0));
  // (at 5 s, while cruising: haul in 1 m at 0.1 m/s) => the planned ramp down is dropped
  const double l5 = w.length(5.0);
  CHECK(startWinch(sp, 0, w, 5.0, -1.0, {0.1}, "b") == Approx(15.0));
  CHECK(w.nextBreak(5.0) == std::numeric_limits<double>::infinity());
  CHECK(w.rate(6.0) == -0.1);
  CHECK(w.length(15.0) == Approx(l5 - 1.0).epsilon(1e-14));
  CHECK(sp.winches[0].actor == "b");
}
