// The AccelerationSource wrapper: tau, a force callback evaluated at every stage, ABA for trees.
#include <catch2/catch.hpp>

#include "dynamics/aba.hpp"
#include "dynamics/configuration.hpp"
#include "dynamics/integrators/rk4.hpp"
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

TEST_CASE("a diverging integration stops with a diagnosis naming the body") {
  ModelBuilder b;
  b.addBody("hook", "world", Joint::prismatic(Vector3::UnitZ()), {}, boxInertia(1.0, Vector3(1, 1, 1)));
  const Model m = b.build();
  MultibodySystem sys(m);
  // a very stiff rope (1e8 N/m on 1 kg) with a step 1000 times its stability limit
  sys.setForces([](double, const Eigen::VectorXd& q, const Eigen::VectorXd&, const Data&, ExternalForces&, Eigen::VectorXd& tau) {
    tau[0] = -1e8 * q[0];
  });
  Rk4 rk(m);
  Eigen::VectorXd q = Eigen::VectorXd::Constant(1, 0.1), v = Eigen::VectorXd::Zero(1);
  double t = 0.0;
  auto run = [&] {
    for (int k = 0; k < 1000; ++k) rk.step(sys, t, q, v, 0.1);
  };
  CHECK_THROWS_AS(run(), IntegrationError);
  q.setConstant(0.1);
  v.setZero();
  t = 0.0;
  CHECK_THROWS_WITH(run(), Catch::Matchers::Contains("body 'hook'") && Catch::Matchers::Contains("smaller step"));
}
