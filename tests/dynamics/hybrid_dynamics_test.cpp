// Hybrid dynamics against ABA: prescribing some dofs' accelerations to what ABA gives must return
// ABA's other accelerations and, as effort, exactly the joint forces that were taken away.
#include <catch2/catch.hpp>

#include "dynamics/aba.hpp"
#include "dynamics/configuration.hpp"
#include "dynamics/crba.hpp"
#include "dynamics/hybrid_dynamics.hpp"
#include "test_models.hpp"

using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;

TEST_CASE("prescribing ABA's own accelerations returns ABA's free accelerations and the removed forces") {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 5; ++trial) {
    const Model m = randomTree(rng, 7);
    const Eigen::VectorXd q = randomConfiguration(m, rng), v = randomVectorX(rng, m.nv);
    const Eigen::VectorXd tau = randomVectorX(rng, m.nv, 5.0);
    ExternalForces f(m);
    f.addWorldFrame(2, randomVectorX(rng, 6, 3.0));
    Data d(m);
    const Eigen::VectorXd aAba = aba(m, d, q, v, tau, &f);
    // (every third dof prescribed, its force removed) => the same motion, the removed force as effort
    std::vector<char> mask(static_cast<std::size_t>(m.nv), 0);
    for (int k = 0; k < m.nv; k += 3) mask[static_cast<std::size_t>(k)] = 1;
    Eigen::VectorXd tauFree = tau, a = Eigen::VectorXd::Zero(m.nv), effort(m.nv);
    for (int k = 0; k < m.nv; ++k)
      if (mask[static_cast<std::size_t>(k)]) {
        tauFree[k] = 0.0;
        a[k] = aAba[k];
      }
    HybridDynamics hd(m);
    hd.setPrescribed(mask);
    REQUIRE(hd.any());
    hd.compute(d, q, v, tauFree, &f, a, effort);
    CHECK(relativeError(a, aAba) < 1e-10);
    for (int k = 0; k < m.nv; ++k)
      CHECK(effort[k] == Approx(mask[static_cast<std::size_t>(k)] ? tau[k] : 0.0).margin(1e-9 * tau.norm()));
  }
}

TEST_CASE("a velocity step on prescribed dofs moves the free ones by an impulse on the prescribed rows only") {
  std::mt19937 rng(11);
  const Model m = randomTree(rng, 6);
  const Eigen::VectorXd q = randomConfiguration(m, rng);
  Eigen::VectorXd v = randomVectorX(rng, m.nv);
  const Eigen::VectorXd v0 = v;
  std::vector<char> mask(static_cast<std::size_t>(m.nv), 0);
  mask[1] = mask[4] = 1;
  Eigen::VectorXd dv = Eigen::VectorXd::Zero(m.nv);
  dv[1] = 0.7;
  dv[4] = -1.3;
  Data d(m);
  HybridDynamics hd(m);
  hd.setPrescribed(mask);
  hd.velocityStep(d, q, v, dv);
  CHECK(v[1] - v0[1] == Approx(0.7));
  CHECK(v[4] - v0[4] == Approx(-1.3));
  // (M (v - v0)) => the impulse: zero on every free row
  const Eigen::VectorXd impulse = crba(m, d, q) * (v - v0);
  for (int k = 0; k < m.nv; ++k)
    if (!mask[static_cast<std::size_t>(k)]) CHECK(impulse[k] == Approx(0.0).margin(1e-10));
}
