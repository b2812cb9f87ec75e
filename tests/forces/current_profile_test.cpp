// Current profiles: uniform, a depth table interpolated linearly and held beyond its ends.
#include <catch2/catch.hpp>

#include <cmath>

#include "forces/current_profile.hpp"

using namespace yardsim::forces;
using yardsim::dynamics::Vector3;

TEST_CASE("uniform and depth-varying current") {
  CurrentProperties p;
  p.speed = 1.5;
  p.direction = M_PI;
  CHECK(CurrentField(p).speedAt(-30.0) == 1.5);
  const Vector3 u = CurrentField(p).velocity(Vector3(0, 0, -3));
  CHECK(u.x() == Approx(-1.5));
  CHECK(std::abs(u.y()) < 1e-12);
  p.level = 1.0;
  p.profile = {{-40.0, 0.0}, {0.0, 1.0}, {-10.0, 0.8}};  // any order
  const CurrentField c(p);
  CHECK(c.speedAt(1.0) == Approx(1.5));           // at the level
  CHECK(c.speedAt(1.0 - 5.0) == Approx(1.5 * 0.9));  // halfway between 0 and -10
  CHECK(c.speedAt(1.0 - 25.0) == Approx(1.5 * 0.4));
  CHECK(c.speedAt(-100.0) == 0.0);                // held below the last entry
  CHECK(c.speedAt(5.0) == Approx(1.5));           // and above the first
  p.profile = {{0.0, 1.0}, {0.0, 0.5}};
  CHECK_THROWS_AS(CurrentField(p), std::invalid_argument);
  p.profile.clear();
  p.speed = NAN;
  CHECK_THROWS_AS(CurrentField(p), std::invalid_argument);
}
