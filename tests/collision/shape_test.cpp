// Shapes: the checks, and the tight world boxes against brute force over the shape's points.
#include "collision/shape.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "dynamics/rotation.hpp"
#include "forces/geometry/primitive_meshes.hpp"

using namespace yardsim::collision;
using yardsim::dynamics::Matrix3;

namespace {

// (rng) => a random rotation (normalised Gaussian quaternion)
Matrix3 randomRotation(std::mt19937& rng) {
  std::normal_distribution<double> n;
  Eigen::Quaterniond q(n(rng), n(rng), n(rng), n(rng));
  q.normalize();
  return q.toRotationMatrix();
}

}  // namespace

TEST_CASE("collision: checkShape refuses non-positive sizes and names the object") {
  CHECK_THROWS_WITH(checkShape(Shape::box(Vector3(1, 0, 1)), "block A"),
                    Catch::Contains("block A") && Catch::Contains("box size"));
  CHECK_THROWS_AS(checkShape(Shape::sphere(-1.0), "s"), CollisionError);
  CHECK_THROWS_AS(checkShape(Shape::cylinder(1.0, std::nan("")), "c"), CollisionError);
  CHECK_THROWS_AS(checkShape(Shape::halfSpace(Vector3::Zero(), 0.0), "g"), CollisionError);
  CHECK_THROWS_AS(checkShape(Shape::triangleMesh(nullptr), "m"), CollisionError);
  CHECK_NOTHROW(checkShape(Shape::capsule(0.1, 0.0), "rope"));
}

TEST_CASE("collision: a rotated box's world box is the box of its eight corners") {
  std::mt19937 rng(3);
  const Shape s = Shape::box(Vector3(4.0, 1.0, 0.5));
  for (int k = 0; k < 50; ++k) {
    const Transform X{randomRotation(rng), Vector3(1.0, -2.0, 3.0)};
    Vector3 lo = Vector3::Constant(1e9), hi = -lo;
    for (int c = 0; c < 8; ++c) {
      const Vector3 p_B(c & 1 ? 2.0 : -2.0, c & 2 ? 0.5 : -0.5, c & 4 ? 0.25 : -0.25);
      lo = lo.cwiseMin(X.actPoint(p_B));
      hi = hi.cwiseMax(X.actPoint(p_B));
    }
    const Aabb b = worldAabb(s, shapeBound(s), X);
    CHECK((b.min - lo).norm() < 1e-12);
    CHECK((b.max - hi).norm() < 1e-12);
  }
}

TEST_CASE(
    "collision: cylinder and capsule boxes are tight: the rim and the end spheres touch them") {
  std::mt19937 rng(5);
  const double r = 0.7, L = 3.0;
  for (int k = 0; k < 20; ++k) {
    const Transform X{randomRotation(rng), Vector3(0.5, 0.5, 0.5)};
    Vector3 lo = Vector3::Constant(1e9), hi = -lo;
    for (int i = 0; i < 20000; ++i) {  // the two rims
      const double th = 2.0 * M_PI * i / 20000.0;
      for (double z : {-0.5 * L, 0.5 * L}) {
        const Vector3 p = X.actPoint(Vector3(r * std::cos(th), r * std::sin(th), z));
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
      }
    }
    const Shape cyl = Shape::cylinder(r, L);
    const Aabb b = worldAabb(cyl, shapeBound(cyl), X);
    CHECK(((b.max - hi).array() >= -1e-12).all());  // encloses
    CHECK((b.max - hi).norm() < 1e-6);              // and touches
    CHECK((lo - b.min).norm() < 1e-6);
    const Shape cap = Shape::capsule(r, L);
    const Aabb c = worldAabb(cap, shapeBound(cap), X);
    const Vector3 e0 = X.actPoint(Vector3(0, 0, -0.5 * L)), e1 = X.actPoint(Vector3(0, 0, 0.5 * L));
    CHECK((c.min - (e0.cwiseMin(e1) - Vector3::Constant(r))).norm() < 1e-12);
    CHECK((c.max - (e0.cwiseMax(e1) + Vector3::Constant(r))).norm() < 1e-12);
    const Aabb s = segmentAabb(e0, e1, r);
    CHECK((s.min - c.min).norm() < 1e-12);
  }
}

TEST_CASE("collision: a mesh's world box encloses its vertices and equals the primitive box's") {
  std::mt19937 rng(7);
  auto mesh = std::make_shared<yardsim::forces::TriangleMesh>(
      yardsim::forces::boxMesh(Vector3(2.0, 3.0, 4.0), 2, 2, 2));
  const Shape m = Shape::triangleMesh(mesh), b = Shape::box(Vector3(2.0, 3.0, 4.0));
  for (int k = 0; k < 20; ++k) {
    const Transform X{randomRotation(rng), Vector3(-3.0, 0.0, 7.0)};
    const Aabb am = worldAabb(m, shapeBound(m), X), ab = worldAabb(b, shapeBound(b), X);
    CHECK((am.min - ab.min).norm() < 1e-12);
    CHECK((am.max - ab.max).norm() < 1e-12);
  }
}

TEST_CASE("collision: a half-space's box is cut on the side its world normal points to") {
  const Shape ground = Shape::halfSpace(Vector3(0, 0, 2.0), 1.0);  // z <= 0.5 in B
  const Aabb a = worldAabb(ground, shapeBound(ground), Transform::translation(Vector3(0, 0, 2)));
  CHECK(a.max.z() == Approx(2.5));
  CHECK(a.min.z() == -kWorldExtent);
  CHECK(a.max.x() == kWorldExtent);
  const Transform flipped{yardsim::dynamics::axisRotation(Vector3::UnitX(), M_PI), Vector3::Zero()};
  const Aabb f = worldAabb(ground, shapeBound(ground), flipped);  // normal -z: z >= -0.5
  CHECK(f.min.z() == Approx(-0.5));
  CHECK(f.max.z() == kWorldExtent);
}
