// Wind profiles: the power law, the NPD (Froya) profile and its gust factor (values computed by
// hand from DNV-RP-C205 eq. 2.3.2.11), the minimum height, gusts added to the mean at every
// height along the direction, and the refused inputs.
#include <catch2/catch.hpp>

#include <cmath>

#include "forces/wind_profile.hpp"

using namespace yardsim::forces;
using yardsim::dynamics::Vector3;

TEST_CASE("power law: U_ref (z / z_ref)^alpha, blowing towards the direction") {
  WindProperties p;
  p.speed = 20.0;
  p.referenceHeight = 10.0;
  p.exponent = 0.11;
  p.direction = M_PI / 2;
  p.level = 2.0;
  const WindField w(p);
  CHECK(w.speedAt(10.0) == Approx(20.0));
  CHECK(w.speedAt(40.0) == Approx(20.0 * std::pow(4.0, 0.11)));
  CHECK(w.speedAt(0.2) == Approx(w.speedAt(1.0)));  // below the minimum height: held
  const Vector3 u = w.velocity(Vector3(5, 5, 12.0), 0.0);  // 10 m above the level
  CHECK(std::abs(u.x()) < 1e-12);
  CHECK(u.y() == Approx(20.0));
  CHECK(u.z() == 0.0);
}

TEST_CASE("NPD profile: 1-hour mean at 10 m, gust factors for shorter averaging times") {
  WindProperties p;
  p.profile = WindProfileKind::Npd;
  p.speed = 40.0;
  CHECK(WindField(p).speedAt(10.0) == Approx(40.0));
  // hand values of U0 [1 + C ln(z/10)] [1 - 0.41 Iu ln(t/3600)] for U0 = 40 m/s
  p.averagingTime = 3.0;
  CHECK(WindField(p).speedAt(10.0) == Approx(58.976449).epsilon(1e-7));
  p.averagingTime = 600.0;
  CHECK(WindField(p).speedAt(50.0) == Approx(53.885954).epsilon(1e-7));
  p.averagingTime = 60.0;
  CHECK(WindField(p).speedAt(2.0) == Approx(42.122527).epsilon(1e-7));
  // shorter averaging => stronger gusts
  double prev = 0.0;
  for (double t : {3600.0, 600.0, 60.0, 3.0}) {
    p.averagingTime = t;
    const double u = WindField(p).speedAt(25.0);
    CHECK(u > prev);
    prev = u;
  }
}

TEST_CASE("bad wind properties are refused") {
  WindProperties p;
  p.speed = -1.0;
  CHECK_THROWS_AS(WindField(p), std::invalid_argument);
  p = {};
  p.profile = WindProfileKind::Npd;
  p.referenceHeight = 20.0;
  CHECK_THROWS_AS(WindField(p), std::invalid_argument);
  p = {};
  p.averagingTime = 7200.0;
  CHECK_THROWS_AS(WindField(p), std::invalid_argument);
  CHECK(windProfileKind("npd") == WindProfileKind::Npd);
  CHECK_THROWS_AS(windProfileKind("log"), std::invalid_argument);
}

TEST_CASE("gusts add one series to the NPD profile's 1-hour mean at every height") {
  WindProperties p;
  p.profile = WindProfileKind::Npd;
  p.speed = 15.0;
  p.direction = 0.4;
  p.level = 1.0;
  WindProperties steady = p;
  p.gusts = GustProperties{};
  const WindField w(p), s(steady);
  REQUIRE(w.gusts() != nullptr);
  CHECK(s.gusts() == nullptr);
  bool varies = false;
  for (double t : {0.0, 13.7, 250.0, 1800.5}) {
    const double g = w.gust(t);
    CHECK(g == w.gusts()->speed(t));
    varies = varies || std::abs(g) > 0.3;
    for (double z : {3.0, 11.0, 40.0}) {
      const Vector3 u = w.velocity(Vector3(7, -2, z), t);
      CHECK(u.x() == Approx((s.speedAt(z - 1.0) + g) * std::cos(0.4)));
      CHECK(u.y() == Approx((s.speedAt(z - 1.0) + g) * std::sin(0.4)));
      CHECK(u.z() == 0.0);
    }
    // (a steady wind) => the same velocity at every time
    CHECK(s.velocity(Vector3(7, -2, 11), t) == s.velocity(Vector3(7, -2, 11), 0.0));
  }
  CHECK(varies);
}

TEST_CASE("gusts are refused on another profile than NPD or with another averaging time") {
  WindProperties p;
  p.speed = 15.0;
  p.gusts = GustProperties{};
  CHECK_THROWS_WITH(WindField(p), Catch::Contains("profile: npd"));  // power law
  p.profile = WindProfileKind::Npd;
  p.averagingTime = 60.0;
  CHECK_THROWS_WITH(WindField(p), Catch::Contains("averaging_time must be 3600"));
  p.averagingTime = 3600.0;
  p.gusts->components = 0;
  CHECK_THROWS_WITH(WindField(p), Catch::StartsWith("components"));
}
