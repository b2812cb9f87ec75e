// The serial N_Vectors whose empty clones come from a pool (sundials_vector_pool.hpp): clones and
// empty clones behave as the serial implementation's, the pool's vectors are handed out and taken
// back, the others freed (run under valgrind or ASan for the frees); and, through CVODE and
// ARKODE, each dense difference-quotient Jacobian takes one empty vector from the pool, which
// counts SUNDIALS' Jacobians independently of IntegratorStats::jac_evals.
#include <catch2/catch.hpp>

#include <vector>

#include "../test_mechanisms.hpp"
#include "dynamics/integrators/adaptive_integrator.hpp"
#include "dynamics/integrators/factory.hpp"
#include "dynamics/integrators/sundials_vector_pool.hpp"
#include "dynamics/multibody_system.hpp"
#include "integrator_cases.hpp"

using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;

namespace {
struct Context {
  SUNContext ctx = nullptr;
  Context() { REQUIRE(SUNContext_Create(nullptr, &ctx) == 0); }
  ~Context() { SUNContext_Free(&ctx); }
};
}  // namespace

TEST_CASE("pooled N_Vectors clone as serial ones, their empty clones come from the pool") {
  Context c;
  SundialsVectorPool pool(c.ctx, 5);
  N_Vector y = pool.makeVector();
  REQUIRE(N_VGetVectorID(y) == SUNDIALS_NVEC_SERIAL);
  REQUIRE(N_VGetLength(y) == 5);
  for (int i = 0; i < 5; ++i) NV_Ith_S(y, i) = i + 1.0;
  // (a clone, a clone of the clone) => own data of the same length, independent of y's
  N_Vector a = N_VClone(y);
  N_Vector b = N_VClone(a);
  REQUIRE(N_VGetLength(b) == 5);
  N_VLinearSum(2.0, y, -1.0, y, a);  // a = y
  N_VScale(3.0, a, b);
  for (int i = 0; i < 5; ++i) {
    CHECK(NV_Ith_S(a, i) == i + 1.0);
    CHECK(NV_Ith_S(b, i) == 3.0 * (i + 1.0));
  }
  CHECK(N_VGetArrayPointer(a) != N_VGetArrayPointer(y));
  // (empty clones of a clone, as SUNDIALS' Jacobian takes them) => the pool's, in turn, no data;
  // given back at N_VDestroy (the array they pointed to untouched) and taken again
  std::vector<double> column(5, 7.0);
  N_Vector e1 = N_VCloneEmpty(b);
  CHECK(N_VGetArrayPointer(e1) == nullptr);
  N_VSetArrayPointer(column.data(), e1);
  N_VScale(2.0, y, e1);
  CHECK(column[4] == 10.0);
  N_Vector e2 = N_VCloneEmpty(y);
  CHECK(e2 != e1);
  CHECK(pool.served() == 2);
  CHECK(pool.allocated() == 0);
  N_VDestroy(e1);
  CHECK(column[4] == 10.0);
  N_Vector e3 = N_VCloneEmpty(a);
  CHECK(e3 == e1);
  CHECK(N_VGetArrayPointer(e3) == nullptr);
  // (more out at once than the pool holds) => a new one, freed at its N_VDestroy
  N_Vector e4 = N_VCloneEmpty(a);
  CHECK(pool.allocated() == 1);
  CHECK(N_VGetLength(e4) == 5);
  N_VDestroy(e4);
  N_VDestroy(e3);
  N_VDestroy(e2);
  // (arrays of clones, as CVODE's and ARKODE's history) => made and freed through the same
  // operations
  N_Vector* zn = N_VCloneVectorArray(3, a);
  N_VConst(1.5, zn[2]);
  CHECK(NV_Ith_S(zn[2], 0) == 1.5);
  N_VDestroyVectorArray(zn, 3);
  N_VDestroy(b);
  N_VDestroy(a);
  N_VDestroy(y);
}

TEST_CASE("an empty clone still out when its pool is freed is freed by its N_VDestroy") {
  Context c;
  N_Vector y = nullptr, e = nullptr;
  {
    SundialsVectorPool pool(c.ctx, 3, 1);
    y = pool.makeVector();
    e = N_VCloneEmpty(y);
    N_VDestroy(y);
  }
  N_VDestroy(e);  // (valgrind, ASan: no leak, no use after free)
  SUCCEED();
}

TEST_CASE("each SUNDIALS dense Jacobian takes one pooled vector and is counted in jac_evals") {
  // (CVODE's and ARKODE's implicit methods with their own difference-quotient Jacobian, on a tree
  // whose solver continues its history and on a four-bar whose solver restarts at every step
  // after the projection) => the pool served one empty clone per Jacobian (cvLsDenseDQJac,
  // arkLsDenseDQJac) and allocated none; IntegratorStats::jac_evals counts the same Jacobians,
  // the first after each re-initialisation included (SUNDIALS resets its count inside the next
  // step), so on the four-bar at least one a step
  std::mt19937 rng(7);
  const Model tree = randomTree(rng, 8);
  const FourBar fb = makeFourBar(1.0, 2.0, 1.5, 2.0);
  for (const Model* m : {&tree, &fb.model}) {
    for (const char* method : {"cvode_bdf", "cvode_adams", "arkode_dirk", "arkode_imex"}) {
      INFO(method << (m == &tree ? " on the tree" : " on the four-bar"));
      IntegratorSpec s = specOf(method);
      s.dt = 1e-3;
      MultibodySystem sys(*m);
      configureLoopStabilization(s, sys);
      const auto integ = makeIntegrator(s, *m);
      const auto* adaptive = dynamic_cast<const AdaptiveIntegrator*>(integ.get());
      REQUIRE(adaptive != nullptr);
      Eigen::VectorXd q = m == &tree ? randomConfiguration(*m, rng) : fb.closedConfiguration(0.3);
      Eigen::VectorXd v = Eigen::VectorXd::Zero(m->nv);
      double t = 0.0;
      const int steps = 25;
      for (int k = 0; k < steps; ++k) integ->step(sys, t, q, v, s.dt);
      const SundialsVectorPool& pool = adaptive->vectorPool();
      CHECK(pool.allocated() == 0);
      CHECK(pool.served() >= 1);
      CHECK(integ->stats().jac_evals == static_cast<long>(pool.served()));
      if (m == &fb.model) CHECK(integ->stats().jac_evals >= steps);
    }
  }
}
