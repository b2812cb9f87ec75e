// Once set up (the first step), a step of any integrator allocates nothing: every global
// operator new of this executable is counted.
#include <catch2/catch.hpp>

#include "support/allocation_counter.hpp"

#include "../test_mechanisms.hpp"
#include "dynamics/integrators/factory.hpp"
#include "dynamics/integrators/sparse_newton_matrix.hpp"
#include "dynamics/multibody_system.hpp"
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

TEST_CASE("the sparse Newton matrix solves without allocating") {
  // (a random tree with a pattern that couples every dof; F_q, F_v formed and factorised) =>
  // its solves, once per Newton iteration of HHT and generalized-alpha, allocate nothing (SparseLU
  // itself allocates a work vector in every solve); the bordered band path (the pattern is within
  // its band) neither solves nor refactorises with an allocation
  const bool band = GENERATE(true, false);
  std::mt19937 rng(7);
  const Model tree = randomTree(rng, 8);
  JacobianPattern pattern;
  pattern.n = tree.nv;
  for (int j = 0; j < tree.nv; ++j) {
    pattern.rows.emplace_back();
    for (int i = 0; i < tree.nv; ++i) pattern.rows.back().push_back(i);
  }
  MultibodySystem sys(tree);
  SparseNewtonMatrix A(tree, pattern, nullptr, band);
  CHECK(A.banded() == band);
  const Eigen::VectorXd q = randomConfiguration(tree, rng);
  const Eigen::VectorXd v = Eigen::VectorXd::Constant(tree.nv, 0.1),
                        delta = Eigen::VectorXd::Zero(tree.nv);
  Eigen::VectorXd f(tree.nv), x(tree.nv), b = Eigen::VectorXd::LinSpaced(tree.nv, -1.0, 1.0);
  sys.unconstrainedAcceleration(0.0, q, v, f);
  A.form([&](const Eigen::VectorXd& qs, const Eigen::VectorXd& vs, bool,
             Eigen::VectorXd& out) { sys.unconstrainedAcceleration(0.0, qs, vs, out); },
         q, delta, q, v, f);
  REQUIRE(A.factorise(0.25e-6, 0.5e-3));
  A.solve(b, x);
  const Eigen::VectorXd first = x;
  const std::size_t before = allocationCount();
  for (int k = 0; k < 100; ++k) A.solve(b, x);
  CHECK(allocationCount() == before);
  if (band) {
    for (int k = 0; k < 10; ++k) REQUIRE(A.factorise(0.25e-6, 0.5e-3));
    CHECK(allocationCount() == before);
  }
  // (the same solution as Eigen's SparseLU::solve of the dense A) => the solve is right
  const Eigen::MatrixXd dense =
      Eigen::MatrixXd::Identity(tree.nv, tree.nv) - 0.25e-6 * A.denseFq() - 0.5e-3 * A.denseFv();
  CHECK((dense * x - b).lpNorm<Eigen::Infinity>() < 1e-12);
  CHECK(x == first);
}
