// The 6x6 added mass against closed forms: a sphere in unbounded fluid (0.5 rho V in every
// translation, no coupling, second-order convergence, the rigid shift to another reference
// point) and a floating hemisphere at infinite frequency (heave 0.5 rho (2/3) pi a^3, the odd
// image of the full sphere); symmetry to solver accuracy.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "dynamics/spatial.hpp"
#include "forces/geometry/primitive_meshes.hpp"
#include "forces/hydro/added_mass.hpp"
#include "forces/hydro/hull_shapes.hpp"
#include "forces/hydro/wetted_surface.hpp"

using namespace yardsim::forces::hydro;

namespace {

constexpr double kRho = 1025.0;
constexpr double kPi = std::numbers::pi;

Matrix6 sphereAddedMass(double a, int n, const Vector3& reference = Vector3::Zero()) {
  AddedMassOptions o;
  o.rho = kRho;
  o.reference = reference;
  return addedMass(cubeSphere(a, n), o);
}

// (A) => largest |A_ij - A_ji| relative to the largest |A_ij|
double asymmetry(const Matrix6& A) { return (A - A.transpose()).cwiseAbs().maxCoeff() / A.cwiseAbs().maxCoeff(); }

}  // namespace

TEST_CASE("sphere in unbounded fluid: 0.5 rho V in each translation, converging at second order") {
  const double a = 2.0;
  const double exact = 0.5 * kRho * 4.0 / 3.0 * kPi * a * a * a;
  const Matrix6 coarse = sphereAddedMass(a, 8);  // 384 panels
  const Matrix6 fine = sphereAddedMass(a, 16);   // 1,536 panels
  for (int i = 0; i < 3; ++i) {
    CHECK(std::abs(fine(i, i) / exact - 1.0) < 0.005);
    const double order = std::log2((coarse(i, i) - exact) / (fine(i, i) - exact));
    CHECK(order > 1.8);
    CHECK(order < 2.3);
  }
  // no coupling between translations nor between translations and rotations (the cube sphere is
  // symmetric about its centre); the rotational added mass, zero for a sphere, is a faceting error
  // that shrinks with the panels
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) {
      if (i != j) CHECK(std::abs(fine(i, j)) < 1e-12 * exact * a * a);
    }
  }
  for (int i = 3; i < 6; ++i) {
    CHECK(fine(i, i) < 1e-6 * exact * a * a);
    CHECK(fine(i, i) < 0.25 * coarse(i, i));
  }
  CHECK(asymmetry(fine) < 1e-9);
}

TEST_CASE("sphere about an off-centre reference point: the rigid shift of 0.5 rho V") {
  // about x_R the rotational normal (x - x_R) x n = -x_R x n (n is radial), so
  // A = m [[I, [x_R]x], [-[x_R]x, -[x_R]x^2]] with m = 0.5 rho V
  const double a = 1.0;
  const Vector3 R(0.7, -0.4, 1.1);
  const double m = 0.5 * kRho * 4.0 / 3.0 * kPi * a * a * a;
  const Eigen::Matrix3d S = yardsim::dynamics::skew(R);
  Matrix6 expected;
  expected << m * Eigen::Matrix3d::Identity(), m * S, -m * S, -m * S * S;
  const Matrix6 A = sphereAddedMass(a, 12, R);  // 864 panels
  CHECK((A - expected).cwiseAbs().maxCoeff() < 0.005 * m * R.squaredNorm());
  CHECK(asymmetry(A) < 1e-8);
}

TEST_CASE("floating hemisphere at infinite frequency: heave 0.5 rho (2/3) pi a^3") {
  const double a = 3.0;
  AddedMassOptions o;
  o.rho = kRho;
  o.solver.freeSurface = FreeSurface::NegativeImage;
  const PanelMesh wet = wettedSurface(cubeSphere(a, 16));
  REQUIRE(wet.panelCount() == 768);
  const Matrix6 A = addedMass(wet, o);
  const double exact = 0.5 * kRho * 2.0 / 3.0 * kPi * a * a * a;
  CHECK(std::abs(A(2, 2) / exact - 1.0) < 0.005);
  // the image makes surge and sway differ from heave (no closed form), symmetric in x and y
  CHECK(A(0, 0) == Approx(A(1, 1)).epsilon(1e-9));
  CHECK(std::abs(A(0, 0) / A(2, 2) - 1.0) > 0.05);
  CHECK(asymmetry(A) < 1e-6);
  // the same problem without the image is the full sphere's half-body in unbounded fluid:
  // different, so the image is really there
  o.solver.freeSurface = FreeSurface::None;
  CHECK(std::abs(addedMass(wet, o)(2, 2) / exact - 1.0) > 0.05);
}

TEST_CASE("a floating hull's added mass in body axes does not depend on its yaw") {
  // a box barge 20 x 8 x 4 m, body origin at mid-depth, floating at 2 m draft: the wetted
  // surface is the same in the body frame whatever the heading, so A in body axes is too
  const PanelMesh hull = yardsim::forces::hydro::panelMesh(yardsim::forces::boxMesh(Vector3(20.0, 8.0, 4.0), 10, 4, 2));
  yardsim::dynamics::Transform X_WB;
  const Matrix6 ahead = floatingAddedMass(hull, X_WB, kRho);
  X_WB.R = Eigen::AngleAxisd(1.1, Vector3::UnitZ()).toRotationMatrix();
  X_WB.p = Vector3(30.0, -7.0, 0.0);
  const Matrix6 turned = floatingAddedMass(hull, X_WB, kRho);
  // (not to round-off: a panel pair at exactly the far-field distance may switch rule)
  CHECK((turned - ahead).cwiseAbs().maxCoeff() < 1e-5 * ahead.cwiseAbs().maxCoeff());
  // a long box: sway added mass well above surge, heave the largest translation
  CHECK(ahead(1, 1) > 2.0 * ahead(0, 0));
  CHECK(ahead(2, 2) > ahead(1, 1));
  // sharp edges and skewed triangles: symmetric to discretisation accuracy only, improving with
  // finer panels
  const Matrix6 finer = floatingAddedMass(
      yardsim::forces::hydro::panelMesh(yardsim::forces::boxMesh(Vector3(20.0, 8.0, 4.0), 20, 8, 4)), {}, kRho);
  CHECK(asymmetry(ahead) < 1e-3);
  CHECK(asymmetry(finer) < 0.5 * asymmetry(ahead));
  // the same pose relative to a still-water level at z = 2 m gives the same matrix
  yardsim::dynamics::Transform X_raised;
  X_raised.p.z() = 2.0;
  const Matrix6 raised = floatingAddedMass(hull, X_raised, kRho, 2.0);
  CHECK((raised - ahead).cwiseAbs().maxCoeff() < 1e-9 * ahead.cwiseAbs().maxCoeff());
  // lifted out of the water it is refused
  X_WB.p.z() = 5.0;
  CHECK_THROWS_WITH(floatingAddedMass(hull, X_WB, kRho), Catch::Matchers::Contains("dry"));
}

TEST_CASE("a bad density is refused") {
  AddedMassOptions o;
  o.rho = 0.0;
  CHECK_THROWS_AS(addedMass(cubeSphere(1.0, 2), o), std::invalid_argument);
}
