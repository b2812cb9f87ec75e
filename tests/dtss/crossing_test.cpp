#include "dtss/crossing.hpp"

#include <catch2/catch.hpp>
#include <cmath>

using namespace yardsim::dtss;

TEST_CASE("crossing directions") {
  CHECK(crosses(1.0, -1.0, Crossing::Falling));
  CHECK_FALSE(crosses(1.0, -1.0, Crossing::Rising));
  CHECK(crosses(-1.0, 0.0, Crossing::Rising));
  CHECK(crosses(-1.0, 2.0, Crossing::Both));
  CHECK_FALSE(crosses(0.0, -1.0, Crossing::Both));  // starting on zero is the previous event
  CHECK_FALSE(crosses(1.0, 2.0, Crossing::Both));
}

TEST_CASE("the located crossing lies just after the true zero, within the tolerance") {
  int evaluations = 0;
  auto g = [&](double t) {
    ++evaluations;
    return std::cos(t);  // falls through zero at pi/2
  };
  for (double tol : {1e-6, 1e-10, 1e-13}) {
    evaluations = 0;
    const double tc = locateCrossing(g, 1.0, std::cos(1.0), 2.0, std::cos(2.0), tol);
    CHECK(tc >= M_PI / 2);
    CHECK(tc - M_PI / 2 <= tol);
    CHECK(std::cos(tc) <= 0.0);
    CHECK(evaluations < 30);  // superlinear, not bisection-slow
  }
  // a stiff, strongly curved function still converges (Illinois keeps the bracket shrinking)
  auto steep = [](double t) { return std::exp(20.0 * (0.3 - t)) - 1.0; };
  const double tc = locateCrossing(steep, 0.0, steep(0.0), 1.0, steep(1.0), 1e-12);
  CHECK(tc == Approx(0.3).margin(1e-12));
}
