// The AccelerationSource wrapper: tau, a force callback evaluated at every stage, ABA for trees.
#include <catch2/catch.hpp>

#include "dynamics/aba.hpp"
#include "dynamics/configuration.hpp"
#include "dynamics/multibody_system.hpp"
#include "test_models.hpp"

using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;

TEST_CASE("the system's acceleration is ABA with the callback's forces") {
  std::mt19937 rng(31);
  const Model m = randomTree(rng, 6);
  MultibodySystem sys(m);
  const Eigen::VectorXd q = randomConfiguration(m, rng), v = randomVectorX(rng, m.nv), tau = randomVectorX(rng, m.nv);
  const Force F = randomVectorX(rng, 6);
  int calls = 0;
  sys.setForces([&](double t, const Eigen::VectorXd&, const Eigen::VectorXd&, const Data& d, ExternalForces& f, Eigen::VectorXd& tq) {
    ++calls;
    CHECK(t == 1.5);
    CHECK(d.X_WB.size() == static_cast<std::size_t>(m.nbodies));
    f.addWorldFrame(3, F);
    tq = tau;
  });
  Eigen::VectorXd a(m.nv);
  sys.acceleration(1.5, q, v, a);
  CHECK(calls == 1);
  Data d(m);
  ExternalForces f(m);
  f.addWorldFrame(3, F);
  CHECK(relativeError(a, aba(m, d, q, v, tau, &f)) < 1e-13);
}

TEST_CASE("constant tau without a callback") {
  const Model m = planarChain(2);
  MultibodySystem sys(m);
  sys.tau() << 1.0, -2.0;
  Data d(m);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(2), v = Eigen::VectorXd::Zero(2), a(2);
  sys.acceleration(0.0, q, v, a);
  CHECK(relativeError(a, aba(m, d, q, v, sys.tau())) < 1e-14);
}
