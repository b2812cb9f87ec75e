// Whole-configuration integrate/difference/neutral on a random tree with every joint type.
#include <catch2/catch.hpp>

#include "dynamics/configuration.hpp"
#include "test_models.hpp"

using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;

TEST_CASE("integrate and difference are inverse over a whole tree") {
  std::mt19937 rng(11);
  const Model m = randomTree(rng, 12);
  const Eigen::VectorXd q0 = randomConfiguration(m, rng);
  const Eigen::VectorXd d = randomVectorX(rng, m.nv, 0.7);
  Eigen::VectorXd q1(m.nq), d2(m.nv);
  integrate(m, q0, d, 1.0, q1);
  difference(m, q0, q1, d2);
  CHECK((d2 - d).norm() < 1e-12);
  Eigen::VectorXd z(m.nv);
  difference(m, q0, q0, z);
  CHECK(z.norm() < 1e-12);
}

TEST_CASE("neutral configuration has unit quaternions and zero differences") {
  std::mt19937 rng(12);
  const Model m = randomTree(rng, 9);
  Eigen::VectorXd q = neutralConfiguration(m);
  Eigen::VectorXd q2 = q;
  normalizeConfiguration(m, q2);
  CHECK((q2 - q).norm() == 0.0);
  CHECK(q.size() == m.nq);
}
