// The spring law: a linear spring's force and energy, a table through its points, its linear
// extension beyond the ends, and its energy against an independent quadrature of its force.
#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

#include "forces/spring_curve.hpp"

using yardsim::forces::SpringCurve;

namespace {
// (curve, a, b) => integral of force from a to b by the composite trapezoid rule on 1e5 panels
// (its error, from the kinks only, is below 1e-9 here)
double trapezoid(const SpringCurve& c, double a, double b) {
  const int n = 100000;
  const double h = (b - a) / n;
  double s = 0.5 * (c.force(a) + c.force(b));
  for (int i = 1; i < n; ++i) s += c.force(a + i * h);
  return s * h;
}
}  // namespace

TEST_CASE("a linear spring: f = k x, V = k x^2 / 2") {
  const SpringCurve c = SpringCurve::linear(250.0);
  CHECK(c.force(-0.4) == Approx(-100.0));
  CHECK(c.stiffness(3.0) == 250.0);
  CHECK(c.energy(-0.4) == Approx(20.0));
  CHECK_THROWS_AS(SpringCurve::linear(-1.0), std::invalid_argument);
  CHECK_THROWS_AS(SpringCurve::linear(NAN), std::invalid_argument);
}

TEST_CASE("a force table: through its points, linear beyond its ends, energy its exact integral") {
  // a progressive spring, stiffer in compression, with its own preload f(0) = 50 N
  const SpringCurve c =
      SpringCurve::table({-0.2, -0.1, 0.0, 0.1, 0.3}, {-900, -300, 50, 200, 1000});
  CHECK(c.force(-0.1) == Approx(-300.0));
  CHECK(c.force(0.05) == Approx(125.0));
  CHECK(c.stiffness(0.05) == Approx(1500.0));
  // beyond the ends: the end segments' slopes (6000 N/m below, 4000 N/m above)
  CHECK(c.force(-0.5) == Approx(-900.0 - 6000.0 * 0.3));
  CHECK(c.force(0.5) == Approx(1000.0 + 4000.0 * 0.2));
  CHECK(c.energy(0.0) == 0.0);
  for (double x : {-0.45, -0.2, -0.13, -0.01, 0.07, 0.1, 0.29, 0.6})
    CHECK(c.energy(x) == Approx(trapezoid(c, 0.0, x)).epsilon(1e-8));
  CHECK_THROWS_AS(SpringCurve::table({0.0, 0.0}, {1.0, 2.0}), std::invalid_argument);
  CHECK_THROWS_AS(SpringCurve::table({0.0}, {1.0}), std::invalid_argument);
  CHECK_THROWS_AS(SpringCurve::table({0.0, 1.0}, {1.0, INFINITY}), std::invalid_argument);
}
