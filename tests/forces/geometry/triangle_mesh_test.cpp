// The enclosed solid's properties against closed forms (box, cylinder, sphere), and the checks
// refusing open, inconsistently oriented, inside-out and degenerate meshes with the source and
// the first offending face in the message.
#include <catch2/catch.hpp>

#include <cmath>

#include "dynamics/rotation.hpp"
#include "forces/geometry/primitive_meshes.hpp"
#include "forces/geometry/triangle_mesh.hpp"

using namespace yardsim;
using namespace yardsim::forces;
using dynamics::Matrix3;
using dynamics::Vector3;
using Catch::Matchers::Contains;

TEST_CASE("a moved and turned box: volume, centroid and inertia of the solid are exact") {
  const Vector3 size(12.0, 5.0, 3.0);
  const dynamics::Transform X{dynamics::eulerToMatrix(Vector3(0.3, -0.2, 1.1)), Vector3(40, -7, 2)};
  const TriangleMesh m = transformed(boxMesh(size, 3, 2, 2), X);
  const SolidProperties p = solidProperties(m);
  const double V = size.prod();
  CHECK(p.volume == Approx(V).epsilon(1e-13));
  CHECK((p.centroid - X.p).norm() < 1e-12);
  // (box about its centre, unit density) => V/12 (b^2 + c^2), ... turned by R
  const Matrix3 I_B = V / 12.0 * Vector3(size.y() * size.y() + size.z() * size.z(),
                                         size.x() * size.x() + size.z() * size.z(),
                                         size.x() * size.x() + size.y() * size.y()).asDiagonal();
  const Matrix3 I_W = X.R * I_B * X.R.transpose();
  CHECK((p.inertia - I_W).norm() < 1e-11 * I_W.norm());
}

TEST_CASE("inscribed cylinders and spheres converge to the round solids at second order") {
  const double r = 2.0, h = 3.0;
  double prevV = 0.0, prevI = 0.0;
  for (int n : {16, 32, 64}) {
    const SolidProperties p = solidProperties(cylinderMesh(r, -1.0, h - 1.0, n));
    // (regular n-gon) => exact polygon area n r^2 sin(2 pi/n)/2
    CHECK(p.volume == Approx(0.5 * n * r * r * std::sin(2 * M_PI / n) * h).epsilon(1e-13));
    CHECK(p.centroid.z() == Approx(0.5).epsilon(1e-13));
    const double eV = std::abs(p.volume - M_PI * r * r * h);
    const double eI = std::abs(p.inertia(2, 2) - 0.5 * M_PI * r * r * h * r * r);
    if (prevV > 0) {
      CHECK(prevV / eV == Approx(4.0).epsilon(0.02));
      CHECK(prevI / eI == Approx(4.0).epsilon(0.03));
    }
    prevV = eV;
    prevI = eI;
  }
  double prev = 0.0;
  for (int n : {16, 32, 64}) {
    const SolidProperties p = solidProperties(sphereMesh(r, n, 2 * n));
    const double e = std::abs(p.volume - 4.0 / 3.0 * M_PI * r * r * r);
    CHECK(p.centroid.norm() < 1e-12);
    CHECK(p.inertia(0, 0) == Approx(p.inertia(2, 2)).epsilon(2.0 / (n * n)));
    if (prev > 0) CHECK(prev / e == Approx(4.0).epsilon(0.03));
    prev = e;
  }
}

TEST_CASE("the primitive meshes pass every check") {
  CHECK_NOTHROW(checkClosedMesh(boxMesh(Vector3(1, 2, 3), 4, 5, 6)));
  CHECK_NOTHROW(checkClosedMesh(cylinderMesh(1.0, 0.0, 2.0, 24, 3)));
  CHECK_NOTHROW(checkClosedMesh(sphereMesh(1.0, 12, 24)));
  // two separate closed parts are a valid solid too (a catamaran)
  TriangleMesh two = boxMesh(Vector3(1, 1, 1));
  const TriangleMesh other = transformed(two, dynamics::Transform::translation(Vector3(5, 0, 0)));
  const int off = static_cast<int>(two.vertices.size());
  two.vertices.insert(two.vertices.end(), other.vertices.begin(), other.vertices.end());
  for (auto t : other.triangles) two.triangles.push_back({t[0] + off, t[1] + off, t[2] + off});
  CHECK_NOTHROW(checkClosedMesh(two));
  CHECK(solidProperties(two).volume == Approx(2.0));
}

TEST_CASE("the checks name the source and the first offending face") {
  TriangleMesh m = boxMesh(Vector3(1, 1, 1));
  m.source = "hull.obj";
  SECTION("an open mesh") {
    m.triangles.erase(m.triangles.begin() + 4);
    CHECK_THROWS_WITH(checkClosedMesh(m), Contains("hull.obj: face ") && Contains("not closed (watertight)"));
  }
  SECTION("one face turned the wrong way") {
    std::swap(m.triangles[5][1], m.triangles[5][2]);
    CHECK_THROWS_WITH(checkClosedMesh(m), Contains("hull.obj: face 5") && Contains("inconsistent orientation"));
  }
  SECTION("every face turned inward") {
    for (auto& t : m.triangles) std::swap(t[1], t[2]);
    CHECK_THROWS_WITH(checkClosedMesh(m), Contains("hull.obj: face 0") && Contains("point inward"));
  }
  SECTION("a repeated vertex") {
    m.triangles[3][1] = m.triangles[3][0];
    CHECK_THROWS_WITH(checkClosedMesh(m), Contains("hull.obj: face 3") && Contains("degenerate"));
  }
  SECTION("a zero-area triangle") {
    m.vertices.push_back(0.5 * (m.vertices[0] + m.vertices[1]));
    m.triangles.push_back({0, 1, static_cast<int>(m.vertices.size()) - 1});
    CHECK_THROWS_WITH(checkClosedMesh(m), Contains("hull.obj: face 12") && Contains("zero area"));
  }
  SECTION("an index outside the vertices") {
    m.triangles[7][2] = 99;
    CHECK_THROWS_WITH(checkClosedMesh(m), Contains("hull.obj: face 7") && Contains("outside the 8 vertices"));
  }
  SECTION("three faces on one edge") {
    const auto t = m.triangles[0];
    m.vertices.push_back(Vector3(3, 3, 3));
    const int k = static_cast<int>(m.vertices.size()) - 1;
    m.triangles.push_back({t[1], t[0], k});  // a fin on face 0's first edge, run the other way
    CHECK_THROWS_AS(checkClosedMesh(m), MeshError);
  }
  SECTION("no triangles") {
    m.triangles.clear();
    CHECK_THROWS_WITH(checkClosedMesh(m), Contains("hull.obj: the mesh has no triangles"));
  }
}
