// Energy, centre of mass and momentum against hand formulas.
#include <catch2/catch.hpp>

#include "dynamics/configuration.hpp"
#include "dynamics/energy.hpp"
#include "dynamics/integrators/rk4.hpp"
#include "dynamics/multibody_system.hpp"
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

TEST_CASE("added mass: kinetic energy 1/2 V (I + A) V and momentum (I + A) V by hand") {
  std::mt19937 rng(22);
  ModelBuilder b;
  const SpatialInertia I = randomInertia(rng);
  const Matrix6 A = randomAddedMass(rng);
  b.addBody("float", "world", Joint::free(), {}, I);
  b.setAddedMass("float", A);
  const Model m = b.build();
  Data d(m);
  Eigen::VectorXd q(7), v(6);
  q << 1, 2, 3, 1, 0, 0, 0;  // identity orientation: body and world axes agree
  v = randomVectorX(rng, 6);
  const Vector6 V = v;
  CHECK(kineticEnergy(m, d, q, v) == Approx(0.5 * V.dot((I.matrix() + A) * V)));
  // momentum about the world origin: the body-origin momentum moved by p = (1, 2, 3)
  const Force h_B = (I.matrix() + A) * V;
  const Force h = momentum(m, d, q, v);
  CHECK((h.tail<3>() - h_B.tail<3>()).norm() < 1e-12);
  CHECK((h.head<3>() - (h_B.head<3>() + Vector3(1, 2, 3).cross(h_B.tail<3>()))).norm() < 1e-11);
  // gravity acts on the rigid mass only
  CHECK(potentialEnergy(m, d, q) == Approx(9.81 * I.mass * (3.0 + I.com.z())));
}

TEST_CASE("a free body with a full added mass conserves energy and momentum (Kirchhoff's equations)") {
  // no gravity, no forces: the body tumbles and drifts with the fluid's Munk moment; T and the
  // world-frame momentum (body + fluid impulse) stay constant, to RK4's accuracy
  std::mt19937 rng(23);
  ModelBuilder b;
  b.setGravity(Vector3::Zero());
  b.addBody("float", "world", Joint::free(), {}, randomInertia(rng));
  b.setAddedMass("float", randomAddedMass(rng));
  const Model m = b.build();
  MultibodySystem system(m);
  Rk4 rk4(m);
  Data d(m);
  Eigen::VectorXd q = randomConfiguration(m, rng), v = randomVectorX(rng, 6);
  double t = 0.0;
  const double T0 = kineticEnergy(m, d, q, v);
  const Force h0 = momentum(m, d, q, v);
  for (int k = 0; k < 2000; ++k) rk4.step(system, t, q, v, 1e-3);
  CHECK(kineticEnergy(m, d, q, v) == Approx(T0).epsilon(1e-9));
  CHECK((momentum(m, d, q, v) - h0).norm() < 1e-8 * h0.norm());
}
