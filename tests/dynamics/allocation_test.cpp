// The algorithms allocate nothing once Data exists: every heap allocation is counted, operator
// new and malloc (Eigen's dynamic-size temporaries bypass operator new).
#include <catch2/catch.hpp>

#include "support/allocation_counter.hpp"

#include "dynamics/aba.hpp"
#include "dynamics/configuration.hpp"
#include "dynamics/constrained_dynamics.hpp"
#include "dynamics/crba.hpp"
#include "dynamics/energy.hpp"
#include "dynamics/integrators/rk4.hpp"
#include "dynamics/integrators/semi_implicit_euler.hpp"
#include "dynamics/multibody_system.hpp"
#include "dynamics/projection.hpp"
#include "dynamics/rnea.hpp"
#include "dynamics/tree_cholesky.hpp"
#include "test_mechanisms.hpp"
#include "test_models.hpp"

using yardsim::testing::allocationCount;

using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;

TEST_CASE("RNEA, ABA, CRBA + Cholesky, energy and RK4 steps do not allocate") {
  std::mt19937 rng(32);
  // second run: every other body carries a full 6x6 added mass
  const bool added = GENERATE(false, true);
  const Model m = randomTree(rng, 24, {0.0, 0.0, -9.81}, added);
  Data d(m);
  ExternalForces f(m);
  MultibodySystem sys(m);
  sys.setForces([](double, const Eigen::VectorXd&, const Eigen::VectorXd&, const Data&, ExternalForces& fx, Eigen::VectorXd&) {
    fx.addWorldFrame(2, Force::Constant(1.0));
  });
  Rk4 rk(m);
  SemiImplicitEuler se(m);
  Eigen::VectorXd q = randomConfiguration(m, rng), v = randomVectorX(rng, m.nv), tau = randomVectorX(rng, m.nv);
  f.addWorldFrame(3, Force::Constant(2.0));
  f.addBodyFrame(4, Force::Constant(1.0));
  double t = 0.0;
  const std::size_t before = allocationCount();
  for (int k = 0; k < 3; ++k) {
    rnea(m, d, q, v, tau, &f);
    rnea(m, d, q, v, tau);
    rneaWorld(m, d, q, v, tau, &f);
    biasForces(m, d, q, v);
    aba(m, d, q, v, tau, &f);
    crba(m, d, q);
    choleskyFactor(m, d);
    choleskySolveInPlace(m, d, d.dv);
    constrainedForwardDynamics(m, d, q, v, tau, &f);
    kineticEnergy(m, d, q, v);
    momentum(m, d, q, v);
    rk.step(sys, t, q, v, 1e-3);
    se.step(sys, t, q, v, 1e-3);
  }
  CHECK(allocationCount() == before);
}

TEST_CASE("closed-loop dynamics and projection do not allocate") {
  const FourBar fb = makeFourBar(1.0, 3.0, 2.5, 3.0);
  Data d(fb.model);
  MultibodySystem sys(fb.model);
  sys.setProjection(true);
  sys.setBaumgarte({1.0, 1.0});
  Rk4 rk(fb.model);
  Eigen::VectorXd q = fb.closedConfiguration(0.5), v = Eigen::VectorXd::Zero(3), tau = Eigen::VectorXd::Zero(3);
  double t = 0.0;
  const std::size_t before = allocationCount();
  for (int k = 0; k < 3; ++k) {
    constrainedForwardDynamics(fb.model, d, q, v, tau);
    rk.step(sys, t, q, v, 1e-3);
    q[2] += 1e-4;
    projectPositions(fb.model, d, q);
    projectVelocities(fb.model, d, q, v);
  }
  CHECK(allocationCount() == before);
}
