// HHT-alpha: the parameters of the family, second order for alpha in [-1/3, 0] (alpha != 0 needs
// the starting procedure), spectral radius (1 + alpha)/(1 - alpha) at high frequency, and closed
// loops held by the index-3 form.
#include <catch2/catch.hpp>

#include "dynamics/integrators/hht.hpp"
#include "dynamics/loop_constraints.hpp"
#include "../test_mechanisms.hpp"
#include "integrator_cases.hpp"

using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;

TEST_CASE("HHT parameters: alpha_m = 0, alpha_f = -alpha, gamma = 1/2 - alpha, beta = (1 - alpha)^2 / 4") {
  const GeneralizedAlphaParameters p = hhtParameters(-0.1);
  CHECK(p.alphaM == 0.0);
  CHECK(p.alphaF == Approx(0.1));
  CHECK(p.gamma == Approx(0.6));
  CHECK(p.beta == Approx(0.3025));
}

TEST_CASE("HHT converges with order 2 on a tree with a free joint for alpha in [-1/3, 0]") {
  const SmoothTree p;
  for (double alpha : {0.0, -0.1, -1.0 / 3.0}) {
    IntegratorSpec s = specOf("hht");
    s.alpha = alpha;
    INFO("alpha " << alpha);
    CHECK(p.observedOrder(s, 50) == Approx(2.0).margin(0.15));
  }
}

TEST_CASE("HHT damps the highest frequencies by (1 + alpha)/(1 - alpha) per step") {
  for (double alpha : {-0.05, -0.1, -0.3}) {
    IntegratorSpec s = specOf("hht");
    s.alpha = alpha;
    Oscillator osc(1e4);
    // (double eigenvalue rho at infinity: amplitude ~ n rho^n) => rho from steps 100 to 200
    const double a100 = osc.amplitude(s, 1.0, 100), a200 = osc.amplitude(s, 1.0, 200);
    INFO("alpha " << alpha << ": " << a100 << " -> " << a200);
    CHECK(std::pow(a200 / a100 / 2.0, 1.0 / 100) == Approx((1 + alpha) / (1 - alpha)).epsilon(0.003));
  }
}

TEST_CASE("HHT on the four-bar and the slider-crank: the loop stays closed at the Newton tolerance") {
  const FourBar fb = makeFourBar(1.0, 2.0, 1.5, 2.0);
  const SliderCrank sc = makeSliderCrank(0.5, 1.5);
  for (const auto& [m, q0] : {std::pair{&fb.model, fb.closedConfiguration(0.3)},
                              std::pair{&sc.model, sc.closedConfiguration(0.4)}}) {
    MultibodySystem sys(*m);
    GeneralizedAlpha hht(*m, hhtParameters(-0.2), "hht");
    Eigen::VectorXd q = q0, v = Eigen::VectorXd::Zero(m->nv);
    Data d(*m);
    double t = 0.0, worst = 0.0;
    for (int k = 0; k < 300; ++k) {  // 6 s at 0.02 s
      hht.step(sys, t, q, v, 0.02);
      worst = std::max(worst, loopResidualNorm(*m, d, q));
    }
    CHECK(worst < 1e-9);
    CHECK(hht.stats().jac_evals < hht.stats().steps);  // the iteration matrix is reused
  }
}
