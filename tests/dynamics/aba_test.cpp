// ABA cross-checks: against CRBA + dense solve, and RNEA(ABA(tau)) = tau, on random trees with
// every joint type, with and without external forces.
#include <catch2/catch.hpp>

#include <Eigen/Cholesky>

#include "dynamics/aba.hpp"
#include "dynamics/configuration.hpp"
#include "dynamics/crba.hpp"
#include "dynamics/rnea.hpp"
#include "test_models.hpp"

using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;

TEST_CASE("ABA = M^-1 (tau - h) and RNEA(ABA(tau)) = tau on random trees") {
  std::mt19937 rng(17);
  for (int trial = 0; trial < 12; ++trial) {
    const int n = 1 + trial * 3;
    const Model m = randomTree(rng, n);
    INFO("bodies " << n);
    Data d(m);
    const Eigen::VectorXd q = randomConfiguration(m, rng), v = randomVectorX(rng, m.nv), tau = randomVectorX(rng, m.nv);
    ExternalForces f(m);
    for (int i = 1; i < m.nbodies; ++i) {
      if (i % 2) f.addWorldFrame(i, randomVectorX(rng, 6));
      else f.addBodyFrame(i, randomVectorX(rng, 6));
    }
    for (const ExternalForces* fext : {static_cast<const ExternalForces*>(nullptr), static_cast<const ExternalForces*>(&f)}) {
      const Eigen::VectorXd ddq = aba(m, d, q, v, tau, fext);
      const Eigen::MatrixXd M = crba(m, d, q);
      const Eigen::VectorXd h = biasForces(m, d, q, v, fext);
      const Eigen::VectorXd ref = M.ldlt().solve(tau - h);
      CHECK(relativeError(ddq, ref) < 1e-10);
      CHECK(relativeError(rnea(m, d, q, v, ddq, fext), tau) < 1e-10);
    }
  }
}

TEST_CASE("ABA of a fixed-base pendulum gives -g/l sin(theta) for a point-like bob") {
  ModelBuilder b;
  const double l = 2.0, mass = 3.0;
  b.addBody("bob", "world", Joint::revolute(Vector3::UnitY()), {},
            makeInertia(mass, Vector3(0, 0, -l), 1e-9 * Matrix3::Identity()));
  const Model m = b.build();
  Data d(m);
  Eigen::VectorXd q(1), v(1), tau(1);
  q << 0.4;
  v << 0.0;
  tau << 0.0;
  // about +y, a positive angle swings the bob towards +x: gravity pulls it back
  CHECK(aba(m, d, q, v, tau)[0] == Approx(-9.81 / l * std::sin(0.4)).epsilon(1e-8));
}
