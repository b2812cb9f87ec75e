// Panel geometry: area, centroid and normal of known panels, the projection of a slightly warped
// quad on its mean plane, and the errors naming the panel for degenerate or inconsistently
// oriented panels.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "forces/hydro/hull_shapes.hpp"
#include "forces/hydro/panel_geometry.hpp"

using namespace yardsim::forces::hydro;
using Catch::Matchers::Contains;

TEST_CASE("a trapezoid's area, centroid and normal") {
  PanelMesh m;
  m.vertices = {{0, 0, 1}, {4, 0, 1}, {3, 2, 1}, {1, 2, 1}};
  m.addQuad(0, 1, 2, 3);
  const Panel p = buildPanels(m)[0];
  CHECK(p.area == Approx(6.0));
  // centroid of a trapezoid: y = h (a + 2b) / (3 (a + b)) with a = 4 (bottom), b = 2 (top)
  CHECK(p.centroid.x() == Approx(2.0));
  CHECK(p.centroid.y() == Approx(2.0 * (4.0 + 4.0) / (3.0 * 6.0)));
  CHECK(p.centroid.z() == Approx(1.0));
  CHECK(p.normal.isApprox(Vector3::UnitZ()));
  CHECK(p.diameter == Approx(4.0));
}

TEST_CASE("a slightly warped quad is projected on its mean plane") {
  PanelMesh m;
  m.vertices = {{0, 0, 0.01}, {1, 0, -0.01}, {1, 1, 0.01}, {0, 1, -0.01}};
  m.addQuad(0, 1, 2, 3);
  const Panel p = buildPanels(m)[0];
  for (int j = 0; j < 4; ++j) CHECK(p.normal.dot(p.vertices[static_cast<std::size_t>(j)] - p.centroid) == Approx(0.0).margin(1e-15));
  CHECK(p.normal.isApprox(Vector3::UnitZ()));
  CHECK(p.area == Approx(1.0));
}

TEST_CASE("the panels of a closed hull have outward normals and their areas sum to its surface") {
  const std::vector<Panel> ps = buildPanels(verticalCylinder(1.5, -2.0, 1.0, 24, 6, 4));
  double area = 0.0;
  Vector3 sumNormal = Vector3::Zero();
  for (const Panel& p : ps) {
    area += p.area;
    sumNormal += p.area * p.normal;
    // outward: the normal points away from the axis or out of the end discs
    const Vector3 c = p.centroid;
    CHECK(p.normal.dot(Vector3(c.x(), c.y(), c.z() - (-0.5))) > 0.0);
  }
  // a 24-gon prism: 2 * 24 * (1/2) r^2 sin(2 pi / 24) + 24 * side * height
  const double r = 1.5, side = 2 * r * std::sin(std::numbers::pi / 24);
  CHECK(area == Approx(24 * r * r * std::sin(2 * std::numbers::pi / 24) + 24 * side * 3.0));
  CHECK(sumNormal.norm() == Approx(0.0).margin(1e-12));
}

TEST_CASE("degenerate panels are refused with an error naming the panel") {
  PanelMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}, {0.75, 1.2, 0}};
  SECTION("repeated vertex") {
    m.addTriangle(0, 1, 2);
    m.addQuad(0, 1, 1, 3);
    CHECK_THROWS_WITH(buildPanels(m), Contains("panel 1 (vertices 0, 1, 1, 3)") && Contains("repeated"));
  }
  SECTION("collinear corners") {
    m.addTriangle(0, 1, 4);
    CHECK_THROWS_WITH(buildPanels(m), Contains("panel 0 (vertices 0, 1, 4)") && Contains("zero area"));
  }
  SECTION("index out of range") {
    m.addTriangle(0, 1, 7);
    CHECK_THROWS_WITH(buildPanels(m), Contains("panel 0") && Contains("vertex index 7 outside 0..5"));
  }
  SECTION("bow-tie quad") {
    m.addQuad(0, 4, 3, 5);
    CHECK_THROWS_AS(buildPanels(m), PanelError);
    CHECK_THROWS_WITH(buildPanels(m), Contains("panel 0") && Contains("bow-tie"));
  }
  SECTION("warped quad") {
    m.vertices[2].z() = 0.8;
    m.addQuad(0, 1, 2, 3);
    CHECK_THROWS_WITH(buildPanels(m), Contains("panel 0") && Contains("warped"));
  }
}

TEST_CASE("an inconsistently oriented panel is refused naming both panels") {
  PanelMesh m = verticalCylinder(1.0, -1.0, 0.0, 8, 2, 2);
  CHECK_NOTHROW(buildPanels(m));
  auto& q = m.panels[5];
  std::swap(q[1], q[3]);  // flip panel 5
  CHECK_THROWS_WITH(buildPanels(m), Contains("panel 5") && Contains("inconsistent orientation"));
}
