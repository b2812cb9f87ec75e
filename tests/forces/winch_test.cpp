// The winch: L0(t) piecewise linear through set-points at exact times, continuous at each,
// held at the minimum length while hauling in, set-points in time order.
#include <catch2/catch.hpp>

#include <stdexcept>

#include "forces/winch.hpp"

using namespace yardsim::forces;

TEST_CASE("the unstretched length follows the payout set-points exactly") {
  Winch w(30.0, 1.0);
  CHECK(w.length(-100.0) == 30.0);
  CHECK(w.length(5.0) == 30.0);
  CHECK(w.rate(5.0) == 0.0);
  w.setPayoutRate(10.0, 0.083);
  w.setPayoutRate(20.0, -0.05);
  // (before, between and after the set-points) => L0 by hand
  CHECK(w.length(9.999) == 30.0);
  CHECK(w.length(10.0) == 30.0);
  CHECK(w.length(15.0) == Approx(30.0 + 0.083 * 5.0).epsilon(1e-15));
  CHECK(w.rate(15.0) == 0.083);
  CHECK(w.length(20.0) == Approx(30.83).epsilon(1e-15));
  CHECK(w.length(30.0) == Approx(30.83 - 0.5).epsilon(1e-15));
  CHECK(w.rate(30.0) == -0.05);
  // (two set-points at the same time) => the later wins, L0 continuous
  w.setPayoutRate(40.0, 0.0);
  w.setPayoutRate(40.0, 0.1);
  CHECK(w.length(40.0) == Approx(30.83 - 1.0).epsilon(1e-15));
  CHECK(w.length(41.0) == Approx(30.83 - 0.9).epsilon(1e-15));
}

TEST_CASE("hauling in stops at the minimum length and paying out resumes from it") {
  Winch w(3.0, 1.0);
  w.setPayoutRate(0.0, -0.5);
  CHECK(w.length(2.0) == Approx(2.0).epsilon(1e-15));
  CHECK(w.length(4.0) == 1.0);
  CHECK(w.length(100.0) == 1.0);
  CHECK(w.rate(5.0) == 0.0);
  CHECK(w.rate(1.0) == -0.5);
  w.setPayoutRate(10.0, 0.2);
  CHECK(w.length(15.0) == Approx(2.0).epsilon(1e-15));
}

TEST_CASE("set-points earlier than the last one or not finite are refused") {
  Winch w(10.0, 0.1);
  w.setPayoutRate(5.0, 0.1);
  CHECK_THROWS_AS(w.setPayoutRate(4.0, 0.1), std::invalid_argument);
  CHECK_THROWS_AS(w.setPayoutRate(6.0, std::nan("")), std::invalid_argument);
  CHECK_THROWS_AS(w.setPayoutRate(std::numeric_limits<double>::infinity(), 0.1),
                  std::invalid_argument);
}
