#include "models/replay.hpp"

#include <algorithm>
#include <catch2/catch.hpp>

using namespace yardsim;
using Shape = mechanics::MechanicsSpec::Visual::Shape;

TEST_CASE("a body without geometry is drawn as the uniform box of its mass and inertia") {
  // box 1 x 2 x 3 m, 6 kg: Ixx = m (2^2 + 3^2) / 12 = 6.5, Iyy = 5, Izz = 2.5
  const dynamics::Matrix3 I = dynamics::Vector3(6.5, 5.0, 2.5).asDiagonal();
  const auto b = models::replayShape({}, 6.0, {0.1, 0.2, 0.3}, I);
  CHECK(b.shape == Shape::Box);
  // (box along its principal axes) => the same extents along the body axes
  const dynamics::Vector3 extents = (b.X_BG.R * b.size.asDiagonal()).cwiseAbs().rowwise().sum();
  CHECK(extents[0] == Approx(1.0));
  CHECK(extents[1] == Approx(2.0));
  CHECK(extents[2] == Approx(3.0));
  CHECK(b.X_BG.R.determinant() == Approx(1.0));
  CHECK(b.X_BG.p == dynamics::Vector3(0.1, 0.2, 0.3));  // on the centre of mass
}

TEST_CASE("a given shape is placed on the centre of mass unless it has a pose") {
  mechanics::MechanicsSpec::Visual v;
  v.shape = Shape::Cylinder;
  v.size = {0.5, 2.0, 0.0};
  const auto b = models::replayShape(v, 1.0, {0, 0, -1}, dynamics::Matrix3::Identity());
  CHECK(b.shape == Shape::Cylinder);
  CHECK(b.size == v.size);
  CHECK(b.X_BG.p == dynamics::Vector3(0, 0, -1));
  v.posed = true;
  v.X_BG = dynamics::Transform::translation({5, 0, 0});
  CHECK(models::replayShape(v, 1.0, {0, 0, -1}, dynamics::Matrix3::Identity()).X_BG.p == dynamics::Vector3(5, 0, 0));
}
