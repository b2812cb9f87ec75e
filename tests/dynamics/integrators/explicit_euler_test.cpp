// Explicit Euler: first order when the step halves; on an undamped oscillator the amplitude grows
// by exactly sqrt(1 + (omega h)^2) per step (its amplification matrix has that spectral radius).
#include <catch2/catch.hpp>

#include "integrator_cases.hpp"

using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;

TEST_CASE("explicit Euler converges with order 1 on a tree with a free joint") {
  const SmoothTree p;
  const double order = p.observedOrder(specOf("explicit_euler"), 400);
  CHECK(order == Approx(1.0).margin(0.1));
}

TEST_CASE("explicit Euler grows an undamped mode by sqrt(1 + (omega h)^2) per step") {
  Oscillator osc(2.0);
  const double h = 0.05;
  CHECK(osc.amplitude(specOf("explicit_euler"), h, 100) == Approx(std::pow(1.0 + 0.01, 50.0)).epsilon(1e-12));
}
