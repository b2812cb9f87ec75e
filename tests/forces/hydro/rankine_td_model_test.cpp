// The impulsive decomposition's A_inf (psi_j with psi_j = 0 on the truncated free-surface panels)
// against the existing infinite-frequency added mass (negative image, an unbounded free surface):
// the same problem solved two ways; and the body-axes rotation of the results.
#include <catch2/catch.hpp>

#include <cmath>

#include "forces/hydro/added_mass.hpp"
#include "td_fixtures.hpp"

using namespace yardsim::forces::hydro;
using namespace yardsim::forces::hydro::test;

TEST_CASE("A_inf from psi_j matches the negative-image added mass") {
  const PanelMesh hull = cubeSphere(1.0, 8);
  const yardsim::dynamics::Transform X_WB{};
  const RankineTdModel model(hull, X_WB, hemisphereSettings(1.0));
  const Matrix6 image = floatingAddedMass(hull, X_WB, kRho);
  INFO("A_inf surge " << model.aInf()(0, 0) / kHemisphereMass << " heave "
                      << model.aInf()(2, 2) / kHemisphereMass << "; image "
                      << image(0, 0) / kHemisphereMass << ", " << image(2, 2) / kHemisphereMass);
  for (int i : {0, 1, 2}) CHECK(model.aInf()(i, i) == Approx(image(i, i)).epsilon(0.01));
  // (the published infinite-frequency values: surge 0.2732, heave 0.5 of rho (2/3) pi a^3; Hulme
  // 1982)
  CHECK(model.aInf()(0, 0) / kHemisphereMass == Approx(0.2732).epsilon(0.03));
  CHECK(model.aInf()(2, 2) / kHemisphereMass == Approx(0.5).epsilon(0.02));
  // symmetric and free of couplings the hemisphere's symmetry forbids
  CHECK((model.aInf() - model.aInf().transpose()).norm() < 1e-3 * model.aInf().norm());
  CHECK(std::abs(model.aInf()(0, 2)) < 1e-3 * model.aInf()(2, 2));
}

TEST_CASE("a hull at a mean pose turned about z gives the same A_inf in body axes") {
  const PanelMesh hull = cubeSphere(1.0, 6);
  yardsim::dynamics::Transform X_WB{};
  X_WB.R = Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  X_WB.p = Eigen::Vector3d(2.0, -1.0, 0.0);
  const RankineTdModel turned(hull, X_WB, hemisphereSettings(1.0));
  const RankineTdModel straight(hull, yardsim::dynamics::Transform{}, hemisphereSettings(1.0));
  const Matrix6 a = toBodyAxes(turned.aInf(), turned.rotation());
  CHECK((a - straight.aInf()).norm() < 0.02 * straight.aInf().norm());
}
