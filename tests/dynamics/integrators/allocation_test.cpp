// Once set up (the first steps), a step of any integrator allocates nothing: every heap
// allocation of this executable is counted, SUNDIALS' included (its dense difference-quotient
// Jacobian's empty vector comes from a pool: dynamics/integrators/sundials_vector_pool.hpp).
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
      const long jacobians = integ->stats().jac_evals;
      const std::size_t before = allocationCount();
      for (int k = 0; k < 20; ++k) integ->step(sys, t, q, v, s.dt);
      const std::size_t blocks = allocationCount() - before;
      INFO(blocks << " heap blocks in 20 steps, " << integ->stats().jac_evals - jacobians
                  << " Jacobians among them");
      CHECK(blocks == 0);
      // (CVODE's and ARKODE's implicit methods on the four-bar: restarted after every projection,
      // so a dense difference-quotient Jacobian at every step) => SUNDIALS' Jacobians were in it
      if (info.adaptive && info.implicit && m == &fb.model)
        CHECK(integ->stats().jac_evals - jacobians >= 20);
    }
  }
}

TEST_CASE("the sparse Newton matrix solves without allocating") {
  // (a random tree with a pattern that couples every dof; F_q, F_v formed and factorised) =>
  // its solves, once per Newton iteration of HHT and generalized-alpha, allocate nothing (SparseLU
  // itself allocates a work vector in every solve), nor do its refactorisations: SparseLU's in the
  // storage of the first (sparse_lu_refactor.hpp; SparseLU::factorize makes 14 blocks each), the
  // bordered band path's (the pattern is within its band)
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
  for (int k = 0; k < 10; ++k) REQUIRE(A.factorise(0.25e-6, 0.5e-3));
  CHECK(allocationCount() == before);
  if (!band) CHECK(A.sparseLu().fullFactorisations() == 1);
  // (the same solution as Eigen's SparseLU::solve of the dense A) => the solve is right
  const Eigen::MatrixXd dense =
      Eigen::MatrixXd::Identity(tree.nv, tree.nv) - 0.25e-6 * A.denseFq() - 0.5e-3 * A.denseFv();
  CHECK((dense * x - b).lpNorm<Eigen::Infinity>() < 1e-12);
  CHECK(x == first);
}

TEST_CASE("HHT and generalized-alpha steps through SparseLU allocate nothing after the first") {
  // (a 40-body random tree, 94 dofs, with a pattern coupling every dof: more far entries than the
  // bordered band LU takes as its border, so the Newton matrix is Eigen's SparseLU) => once the
  // matrix is formed and factorised, steps that reuse it (Newton's solves through
  // SparseNewtonMatrix::solve) allocate nothing, nor do refactorisations ("the sparse Newton
  // matrix solves without allocating").
  std::mt19937 rng(7);
  const Model tree = randomTree(rng, 40);
  auto pattern = std::make_shared<JacobianPattern>();
  pattern->n = tree.nv;
  for (int j = 0; j < tree.nv; ++j) {
    pattern->rows.emplace_back();
    for (int i = 0; i < tree.nv; ++i) pattern->rows.back().push_back(i);
  }
  REQUIRE(!SparseNewtonMatrix(tree, *pattern).banded());
  for (const char* method : {"hht", "generalized_alpha"}) {
    INFO(method);
    MultibodySystem sys(tree);
    sys.setJacobianPattern(pattern);
    IntegratorSpec s = specOf(method);
    s.dt = 1e-3;
    const auto integ = makeIntegrator(s, tree);
    Eigen::VectorXd q = randomConfiguration(tree, rng), v = Eigen::VectorXd::Zero(tree.nv);
    double t = 0.0;
    for (int k = 0; k < 5; ++k) integ->step(sys, t, q, v, s.dt);
    const std::size_t before = allocationCount();
    for (int k = 0; k < 20; ++k) integ->step(sys, t, q, v, s.dt);
    CHECK(allocationCount() == before);
    CHECK(integ->stats().jac_evals >= 1);  // (the sparse matrix was formed)
  }
}
