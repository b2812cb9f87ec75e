// Masses and inertias a body can have, and the ones it cannot.
#include <catch2/catch.hpp>

#include <cmath>

#include "yard/database.hpp"
#include "yard/physical_checks.hpp"

using namespace yardsim::yard;
using Catch::Matchers::Contains;
using yardsim::dynamics::Matrix3;
using yardsim::dynamics::Vector3;

TEST_CASE("masses must be finite and positive") {
  CHECK_NOTHROW(checkMass(920e3, "b"));
  CHECK_THROWS_WITH(checkMass(-5, "b"), Contains("b: the mass must be"));
  CHECK_THROWS_AS(checkMass(0, "b"), DatabaseError);
  CHECK_THROWS_AS(checkMass(NAN, "b"), DatabaseError);
}

TEST_CASE("inertias: a box, a rod and a thin plate pass, a triangle-inequality breach does not") {
  // a box 10 x 4 x 2 m of 1000 kg, turned: its tensor is full but physical
  const Matrix3 box = (1000.0 / 12 * Vector3(16 + 4, 100 + 4, 100 + 16)).asDiagonal();
  const Matrix3 R = Eigen::AngleAxisd(0.6, Vector3(1, 2, 3).normalized()).toRotationMatrix();
  CHECK_NOTHROW(checkInertia(R * box * R.transpose(), "b"));
  // a thin plate meets the bound with equality: Izz = Ixx + Iyy
  CHECK_NOTHROW(checkInertia(Vector3(1, 2, 3).asDiagonal(), "plate"));
  CHECK_THROWS_WITH(checkInertia(Vector3(1, 2, 3.5).asDiagonal(), "b"),
                    Contains("largest principal moment exceeds") && Contains("3.5"));
  // the same breach hidden by a rotation is still found (principal moments, not the diagonal)
  CHECK_THROWS_AS(checkInertia(R * Matrix3(Vector3(1, 2, 3.5).asDiagonal()) * R.transpose(), "b"),
                  DatabaseError);
  CHECK_THROWS_WITH(checkInertia(Vector3(1, -2, 3).asDiagonal(), "b"),
                    Contains("not positive definite"));
  CHECK_THROWS_WITH(checkInertia(Matrix3::Zero(), "b"), Contains("not positive definite"));
  Matrix3 skew = box;
  skew(0, 1) = 5;
  CHECK_THROWS_WITH(checkInertia(skew, "b"), Contains("not symmetric"));
}
