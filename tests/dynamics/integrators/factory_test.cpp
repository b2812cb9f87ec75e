// The method table against the methods themselves: every name builds the integrator of that
// name, bad specs are refused with the key at fault, and each fixed-step method's stability limit
// on the imaginary axis (used by the stiffness guard) is where an undamped oscillator starts to grow.
#include <catch2/catch.hpp>

#include "dynamics/integrators/factory.hpp"
#include "dynamics/loop_constraints.hpp"
#include "../test_mechanisms.hpp"
#include "integrator_cases.hpp"

using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;

TEST_CASE("every listed method builds an integrator of that name that takes a step") {
  Oscillator osc(1.0);
  CHECK(integratorMethods().size() == 13);
  CHECK(integratorMethodNames().size() == 13);
  for (const MethodInfo& m : integratorMethods()) {
    IntegratorSpec s = specOf(std::string(m.name));
    s.dt = 0.01;
    const auto integ = makeIntegrator(s, osc.model);
    CHECK(integ->name() == m.name);
    Eigen::VectorXd q = Eigen::VectorXd::Ones(1), v = Eigen::VectorXd::Zero(1);
    double t = 0.0;
    integ->step(osc, t, q, v, 0.01);
    CHECK(t == Approx(0.01));
    CHECK(q[0] == Approx(std::cos(0.01)).margin(1e-4));
    CHECK(integ->stats().steps >= 1);
    CHECK(integ->stats().f_evals >= 1);
    CHECK(findMethod(m.name) == &m);
  }
  CHECK(findMethod("rk5") == nullptr);
}

TEST_CASE("bad specs are refused naming the key") {
  auto problems = [](IntegratorSpec s) {
    std::string keys;
    for (const auto& p : checkIntegratorSpec(s)) keys += p.key + ";";
    return keys;
  };
  IntegratorSpec s = specOf("hht");
  s.dt = 0.01;
  CHECK(problems(s).empty());
  s.alpha = -0.5;
  CHECK(problems(s) == "alpha;");
  s = specOf("generalized_alpha");
  s.dt = 0.0;
  s.rhoInf = 1.5;
  CHECK(problems(s) == "dt;rho_inf;");
  s = specOf("cvode_bdf");
  s.dt = 0.1;
  s.maxOrder = 6;
  s.rtol = 0.0;
  CHECK(problems(s) == "rtol;max_order;");
  s = specOf("rk5");
  CHECK(problems(s) == "method;");
  CHECK_THROWS_WITH(makeIntegrator(s, Oscillator(1.0).model),
                    Catch::Contains("integrator.method: unknown integration method 'rk5'") && Catch::Contains("ab4"));
}

TEST_CASE("the imaginary-axis stability limits of the table are where an undamped mode starts to grow") {
  Oscillator osc(1.0);
  for (const MethodInfo& m : integratorMethods()) {
    if (m.adaptive) continue;
    INFO(m.name);
    const IntegratorSpec s = specOf(std::string(m.name));
    const int n = 3000;
    if (m.imagStabilityLimit == 0.0) {
      // grows at any step: amplitude factor > 1 per step even at omega h = 0.1
      CHECK(osc.amplitude(s, 0.1, n) > 1.001);
    } else if (m.imagStabilityLimit == kUnconditionallyStable) {
      // bounded at omega h = 1000
      CHECK(osc.amplitude(s, 1000.0, 200) < 1.0 + 1e-9);
    } else {
      const double L = m.imagStabilityLimit;
      const double inside = osc.amplitude(s, 0.97 * L, n), outside = osc.amplitude(s, 1.03 * L, n);
      INFO("limit " << L << ": amplitude " << inside << " inside, " << outside << " outside");
      CHECK(inside < 10.0);
      CHECK(!(outside < 1e3));  // grown (or overflowed)
    }
  }
}

TEST_CASE("loop stabilisation is selectable: projection holds the four-bar closed, Baumgarte bounds the drift") {
  const FourBar fb = makeFourBar(1.0, 2.0, 1.5, 2.0);
  // (stabilisation) => largest residual over the first 2.5 s and over the next 17.5 s
  auto drift = [&](LoopStabilization how, double& early, double& late) {
    IntegratorSpec s = specOf("rk4");
    s.dt = 0.01;
    s.loops = how;
    MultibodySystem sys(fb.model);
    configureLoopStabilization(s, sys);
    const auto integ = makeIntegrator(s, fb.model);
    Eigen::VectorXd q = fb.closedConfiguration(0.3), v = Eigen::VectorXd::Zero(3);
    Data d(fb.model);
    double t = 0.0;
    early = late = 0.0;
    for (int k = 0; k < 2000; ++k) {
      integ->step(sys, t, q, v, s.dt);
      (k < 250 ? early : late) = std::max(k < 250 ? early : late, loopResidualNorm(fb.model, d, q));
    }
  };
  double none0, none1, b0, b1, p0, p1;
  drift(LoopStabilization::None, none0, none1);
  drift(LoopStabilization::Baumgarte, b0, b1);
  drift(LoopStabilization::Projection, p0, p1);
  INFO("none " << none0 << " then " << none1 << ", Baumgarte " << b0 << " then " << b1 << ", projection " << p1);
  CHECK(p1 < 1e-11);
  CHECK(none1 > 3 * none0);  // without stabilisation the residual keeps growing
  CHECK(b1 < 1.5 * b0);      // with Baumgarte it stays bounded
  CHECK(b1 < 0.1 * none1);
}

TEST_CASE("every method keeps the quaternions of ball and free joints at unit length") {
  std::mt19937 rng(11);
  const Model m = randomTree(rng, 7);  // free root, then every joint type (a ball joint among them)
  const Eigen::VectorXd q0 = randomConfiguration(m, rng), v0 = randomVectorX(rng, m.nv, 3.0);
  for (const MethodInfo& info : integratorMethods()) {
    INFO(info.name);
    IntegratorSpec s = specOf(std::string(info.name));
    s.dt = 0.01;
    MultibodySystem sys(m);
    const auto integ = makeIntegrator(s, m);
    Eigen::VectorXd q = q0, v = v0;
    double t = 0.0, worst = 0.0;
    for (int k = 0; k < 50; ++k) {
      integ->step(sys, t, q, v, s.dt);
      for (int i = 1; i < m.nbodies; ++i) {
        const JointType type = m.joints[i].type;
        if (type == JointType::Spherical) worst = std::max(worst, std::abs(q.segment<4>(m.idxQ[i]).norm() - 1.0));
        if (type == JointType::Free) worst = std::max(worst, std::abs(q.segment<4>(m.idxQ[i] + 3).norm() - 1.0));
      }
    }
    CHECK(worst < 1e-14);
  }
}
