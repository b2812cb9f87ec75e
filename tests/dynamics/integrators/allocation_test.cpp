// Once set up (the first step), a step of any integrator allocates nothing: every global
// operator new of this executable is counted.
#include <catch2/catch.hpp>

#include "support/allocation_counter.hpp"

#include "dynamics/integrators/factory.hpp"
#include "../test_mechanisms.hpp"
#include "integrator_cases.hpp"

using yardsim::testing::allocationCount;
using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;

TEST_CASE("integrator steps allocate nothing after the first, on a tree and on a closed loop") {
  std::mt19937 rng(7);
  const Model tree = randomTree(rng, 8);
  const FourBar fb = makeFourBar(1.0, 2.0, 1.5, 2.0);
  for (const Model* m : {&tree, &fb.model}) {
    for (const MethodInfo& info : integratorMethods()) {
      INFO(info.name << (m == &tree ? " on the tree" : " on the four-bar"));
      IntegratorSpec s = specOf(std::string(info.name));
      s.dt = 1e-3;
      MultibodySystem sys(*m);
      configureLoopStabilization(s, sys);
      const auto integ = makeIntegrator(s, *m);
      Eigen::VectorXd q = m == &tree ? randomConfiguration(*m, rng) : fb.closedConfiguration(0.3);
      Eigen::VectorXd v = Eigen::VectorXd::Zero(m->nv);
      double t = 0.0;
      for (int k = 0; k < 5; ++k) integ->step(sys, t, q, v, s.dt);  // set-up, multistep start
      const std::size_t before = allocationCount();
      for (int k = 0; k < 20; ++k) integ->step(sys, t, q, v, s.dt);
      CHECK(allocationCount() == before);
    }
  }
}
