// The AccelerationSource wrapper: tau, a force callback evaluated at every stage, ABA for trees.
#include <catch2/catch.hpp>

#include <limits>

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

TEST_CASE(
    "a non-finite configuration, velocity or acceleration is refused naming the body, a huge "
    "finite one is not") {
  const Model m = planarChain(3);
  MultibodySystem sys(m);
  Eigen::VectorXd a(3);
  const double bad[] = {std::numeric_limits<double>::quiet_NaN(),
                        std::numeric_limits<double>::infinity(),
                        -std::numeric_limits<double>::infinity()};
  for (const double x : bad) {
    for (int k = 0; k < 3; ++k) {
      Eigen::VectorXd q = Eigen::VectorXd::Zero(3), v = Eigen::VectorXd::Zero(3);
      q[k] = x;
      const std::string body = "body '" + m.names[static_cast<std::size_t>(k) + 1] + "'";
      CHECK_THROWS_WITH(sys.acceleration(0.0, q, v, a),
                        Catch::Matchers::Contains("the configuration of " + body));
      q[k] = 0.0;
      v[k] = x;
      CHECK_THROWS_WITH(sys.acceleration(0.0, q, v, a),
                        Catch::Matchers::Contains("the velocity of " + body));
    }
  }
  // (a torque that overflows the acceleration) => refused there
  sys.tau() << 0.0, 0.0, 1e308;
  Eigen::VectorXd q = Eigen::VectorXd::Zero(3), v = Eigen::VectorXd::Zero(3);
  CHECK_THROWS_WITH(sys.acceleration(0.0, q, v, a),
                    Catch::Matchers::Contains("the acceleration of body"));
  // (angles of 1e300 rad, finite) => accepted
  sys.tau().setZero();
  q.setConstant(1e300);
  sys.acceleration(0.0, q, v, a);
  CHECK(a.allFinite());
}

TEST_CASE("a kept stage is the first acceleration after keepNextStage, with its own forces") {
  // forces that change with t: each stage's differ, so a stage kept from another call would show
  std::mt19937 rng(47);
  const Model m = randomTree(rng, 5);
  MultibodySystem sys(m);
  const Force F = randomVectorX(rng, 6);
  sys.setForces([&](double t, const Eigen::VectorXd&, const Eigen::VectorXd&, const Data&,
                    ExternalForces& f, Eigen::VectorXd&) { f.addWorldFrame(2, t * F); });
  const Eigen::VectorXd q1 = randomConfiguration(m, rng), v1 = randomVectorX(rng, m.nv);
  const Eigen::VectorXd q2 = randomConfiguration(m, rng), v2 = randomVectorX(rng, m.nv);
  Eigen::VectorXd a1(m.nv), a2(m.nv), a3(m.nv);
  sys.acceleration(0.5, q2, v2, a3);  // (not asked to keep) => nothing kept
  CHECK_FALSE(sys.keptStage().valid);
  sys.keepNextStage();
  sys.acceleration(1.5, q1, v1, a1);  // kept
  sys.acceleration(2.5, q2, v2, a2);  // a later stage of the same step: not kept
  const MultibodySystem::KeptStage& kept = sys.keptStage();
  REQUIRE(kept.valid);
  CHECK(kept.t == 1.5);
  CHECK(kept.q == q1);
  CHECK(kept.v == v1);
  CHECK(kept.a == a1);  // bit for bit: the copy of the stage's result
  CHECK(kept.forces.worldFrame(2) == 1.5 * F);
  CHECK(kept.forces.worldFrame(1).isZero());
  // (the same stage evaluated again) => the same accelerations as kept, and its forces
  Eigen::VectorXd again(m.nv);
  sys.acceleration(1.5, q1, v1, again);
  CHECK(again == kept.a);
  CHECK(sys.stageExternalForces()->worldFrame(2) == kept.forces.worldFrame(2));
  // (asked again, or dropped) => what was kept is gone until the next evaluation
  sys.keepNextStage();
  CHECK_FALSE(sys.keptStage().valid);
  sys.acceleration(2.5, q2, v2, a3);
  CHECK(sys.keptStage().t == 2.5);
  CHECK(sys.keptStage().forces.worldFrame(2) == 2.5 * F);
  sys.dropKeptStage();
  CHECK_FALSE(sys.keptStage().valid);
  // (asked, then stopped before any evaluation) => nothing kept
  sys.keepNextStage();
  sys.stopKeeping();
  sys.acceleration(1.5, q1, v1, a1);
  CHECK_FALSE(sys.keptStage().valid);
}
