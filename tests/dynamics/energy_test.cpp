// Energy, centre of mass and momentum against hand formulas.
#include <catch2/catch.hpp>

#include "dynamics/energy.hpp"
#include "test_models.hpp"

using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;

TEST_CASE("single rod: energies, centre of mass and momentum by hand") {
  const Model m = planarChain(1);
  Data d(m);
  Eigen::VectorXd q(1), v(1);
  q << 0.3;
  v << 2.0;
  // rod of 1 kg, 1 m about its end: I = 1/3; centre at 0.5 (cos q, 0, -sin q)
  CHECK(kineticEnergy(m, d, q, v) == Approx(0.5 * (1.0 / 3.0 + 1e-6 / 12.0 * 0.0) * 4.0).epsilon(1e-6));
  CHECK(potentialEnergy(m, d, q) == Approx(9.81 * (-0.5 * std::sin(0.3))));
  CHECK((centerOfMass(m, d, q) - Vector3(0.5 * std::cos(0.3), 0.0, -0.5 * std::sin(0.3))).norm() < 1e-15);
  const Force h = momentum(m, d, q, v);
  // linear momentum = m * velocity of the centre: omega = 2 e_y, c = 0.5 (cos, 0, -sin)
  const Vector3 c(0.5 * std::cos(0.3), 0.0, -0.5 * std::sin(0.3));
  CHECK((h.tail<3>() - Vector3(0, 2, 0).cross(c)).norm() < 1e-14);
  // angular momentum about the pivot (world origin) = I_pivot omega
  CHECK(h[1] == Approx(2.0 / 3.0).epsilon(1e-5));
}

TEST_CASE("free body momentum: m v_c and I_c w + c x m v_c") {
  std::mt19937 rng(20);
  ModelBuilder b;
  const SpatialInertia I = randomInertia(rng);
  b.addBody("barge", "world", Joint::free(), {}, I);
  const Model m = b.build();
  Data d(m);
  Eigen::VectorXd q(7), v(6);
  q << 1, 2, 3, 1, 0, 0, 0;  // identity orientation
  v = randomVectorX(rng, 6);
  const Vector3 w = v.head<3>();
  const Vector3 vc = v.tail<3>() + w.cross(I.com);
  const Vector3 c = Vector3(1, 2, 3) + I.com;
  const Force h = momentum(m, d, q, v);
  CHECK((h.tail<3>() - I.mass * vc).norm() < 1e-13);
  CHECK((h.head<3>() - (I.inertiaCom * w + c.cross(I.mass * vc))).norm() < 1e-12);
  CHECK(kineticEnergy(m, d, q, v) == Approx(0.5 * I.mass * vc.squaredNorm() + 0.5 * w.dot(I.inertiaCom * w)));
}
