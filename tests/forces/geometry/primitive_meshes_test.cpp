// The generated solids: sizes, triangle counts, vertices on the round surfaces.
#include <catch2/catch.hpp>

#include "forces/geometry/primitive_meshes.hpp"

using namespace yardsim::forces;
using yardsim::dynamics::Vector3;

TEST_CASE("a box grid has 4 (nx ny + ny nz + nz nx) triangles and its corners at +-size/2") {
  const TriangleMesh m = boxMesh(Vector3(4, 2, 1), 3, 2, 5);
  CHECK(m.triangles.size() == 4u * (3 * 2 + 2 * 5 + 5 * 3));
  CHECK(m.vertices.size() == 2u * (3 * 2 + 2 * 5 + 5 * 3) + 2);  // Euler: V = T/2 + 2
  Vector3 lo = m.vertices[0], hi = m.vertices[0];
  for (const Vector3& v : m.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  CHECK((hi - Vector3(2, 1, 0.5)).norm() == 0.0);
  CHECK((lo + Vector3(2, 1, 0.5)).norm() == 0.0);
  CHECK_THROWS_AS(boxMesh(Vector3(1, 0, 1)), std::invalid_argument);
}

TEST_CASE("cylinder and sphere vertices lie on the round surfaces") {
  const TriangleMesh c = cylinderMesh(1.5, -2.0, 1.0, 20, 4);
  CHECK(c.triangles.size() == 20u * (2 * 4 + 2));
  for (std::size_t i = 0; i + 2 < c.vertices.size(); ++i)
    CHECK(c.vertices[i].head<2>().norm() == Approx(1.5));
  const TriangleMesh s = sphereMesh(2.5, 10, 16);
  CHECK(s.triangles.size() == 2u * 16 * (10 - 1));
  for (const Vector3& v : s.vertices) CHECK(v.norm() == Approx(2.5));
  CHECK_THROWS_AS(sphereMesh(1.0, 1, 8), std::invalid_argument);
  CHECK_THROWS_AS(cylinderMesh(1.0, 1.0, 1.0, 8), std::invalid_argument);
}
