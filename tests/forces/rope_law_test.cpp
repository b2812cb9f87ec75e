// The rope law: tension-only spring-damper on the elongation, strain energy whose derivatives
// are the elastic tension (in L) and the winch term (in L0, checked by central differences),
// the power that closes the energy balance, refused properties.
#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

#include "forces/rope_law.hpp"

using namespace yardsim::forces;
using Catch::Matchers::Contains;

TEST_CASE("tension is k e + c e' while taut and never negative") {
  const double ea = 2e8, c = 3e4;
  // (taut) => EA/L0 (L - L0) + c (L' - L0')
  CHECK(ropeTension(ea, c, {20.1, 0.3, 20.0, 0.1}) ==
        Approx(ea / 20.0 * (20.1 - 20.0) + c * 0.2).epsilon(1e-14));
  CHECK(elasticTension(ea, {20.1, 0.3, 20.0, 0.1}) ==
        Approx(ea / 20.0 * (20.1 - 20.0)).epsilon(1e-14));
  // (slack or just straight) => 0 whatever the rates
  CHECK(ropeTension(ea, c, {19.9, 5.0, 20.0, 0.0}) == 0.0);
  CHECK(ropeTension(ea, c, {20.0, 5.0, 20.0, 0.0}) == 0.0);
  // (taut but shortening fast) => clamped at 0
  CHECK(ropeTension(ea, c, {20.001, -100.0, 20.0, 0.0}) == 0.0);
  // (non-finite length) => NaN comes out, for evaluate() to refuse
  CHECK(std::isnan(ropeTension(ea, c, {std::nan(""), 0.0, 20.0, 0.0})));
}

TEST_CASE("strain energy: dV/dL is the elastic tension and dV/dL0 the winch term") {
  const double ea = 2e8, L = 20.3, l0 = 20.0, h = 1e-5;
  CHECK(strainEnergy(ea, L, l0) == Approx(0.5 * ea / l0 * 0.09).epsilon(1e-12));
  CHECK(strainEnergy(ea, 19.0, l0) == 0.0);
  const double dVdL = (strainEnergy(ea, L + h, l0) - strainEnergy(ea, L - h, l0)) / (2 * h);
  CHECK(dVdL == Approx(elasticTension(ea, {L, 0.0, l0, 0.0})).epsilon(1e-8));
  const double dVdL0 = (strainEnergy(ea, L, l0 + h) - strainEnergy(ea, L, l0 - h)) / (2 * h);
  CHECK(strainEnergyDl0(ea, L, l0) == Approx(dVdL0).epsilon(1e-8));
  CHECK(strainEnergyDl0(ea, 19.0, l0) == 0.0);
}

TEST_CASE("the power is what the tension does beyond -dV/dL plus the winch's change of V") {
  const double ea = 2e8, c = 3e4;
  const int n = 3;
  const RopeStrain s{20.1, 0.3, 20.0, 0.05};
  const double T = ropeTension(ea, c, s);
  // (d/dt of n V along the motion) - (power of the rope on the bodies, -n T L') = power
  const double dt = 1e-6;
  const double dVdt = n *
                      (strainEnergy(ea, s.length + s.lengthRate * dt, s.l0 + s.l0Rate * dt) -
                       strainEnergy(ea, s.length - s.lengthRate * dt, s.l0 - s.l0Rate * dt)) /
                      (2 * dt);
  CHECK(ropePower(ea, T, n, s) == Approx(dVdt - n * T * s.lengthRate).epsilon(1e-7));
  // (slack) => no power
  CHECK(ropePower(ea, 0.0, n, {19.0, 0.3, 20.0, 0.05}) == 0.0);
}

TEST_CASE("rope properties are checked") {
  RopeProperties p;
  p.ea = 1e8;
  p.l0 = 10.0;
  CHECK_NOTHROW(checkRopeProperties(p, "r"));
  p.ea = std::nan("");
  CHECK_THROWS_WITH(checkRopeProperties(p, "main hoist"), Contains("main hoist") && Contains("EA"));
  p.ea = 1e8;
  p.l0 = 0.001;  // below the minimum length
  CHECK_THROWS_AS(checkRopeProperties(p, "r"), std::invalid_argument);
  p.l0 = 10.0;
  p.minLength = 0.0;
  CHECK_THROWS_AS(checkRopeProperties(p, "r"), std::invalid_argument);
  p.minLength = 0.01;
  p.damping = std::numeric_limits<double>::infinity();
  CHECK_THROWS_AS(checkRopeProperties(p, "r"), std::invalid_argument);
  p.damping = 0.0;
  p.breakingLoad = -5.0;
  CHECK_THROWS_AS(checkRopeProperties(p, "r"), std::invalid_argument);
}
