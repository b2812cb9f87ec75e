// External forces: a point force is a world spatial force (p x f, f); frames convert by X^*.
#include <catch2/catch.hpp>

#include "dynamics/external_forces.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/configuration.hpp"
#include "test_models.hpp"

using namespace yardsim::dynamics;
using namespace yardsim::dynamics::testing;

TEST_CASE("point force, frame conversion, clear") {
  std::mt19937 rng(21);
  const Model m = randomTree(rng, 4);
  Data d(m);
  forwardKinematics(m, d, randomConfiguration(m, rng));
  ExternalForces f(m);
  CHECK(f.empty());
  const Vector3 p(1, 2, 3), F(0, 0, -5);
  f.addPointForceWorld(2, p, F);
  CHECK(f.hasWorldFrame());
  CHECK((f.worldFrame(2).head<3>() - p.cross(F)).norm() < 1e-15);
  // in the body frame the moment is about the body origin: (p - o) x F rotated into the body
  const Force F_B = f.inBodyFrame(d, 2);
  const Transform& X = d.X_WB[2];
  CHECK((F_B.tail<3>() - X.R.transpose() * F).norm() < 1e-14);
  CHECK((F_B.head<3>() - X.R.transpose() * (p - X.p).cross(F)).norm() < 1e-13);
  f.addBodyFrame(2, F_B);
  CHECK((f.inBodyFrame(d, 2) - 2.0 * F_B).norm() < 1e-13);
  f.clear();
  CHECK(f.empty());
  CHECK(f.inBodyFrame(d, 2).norm() == 0.0);
}
