// Free-surface panels round a floating hemisphere: the waterline loop, the rings from the
// waterline to the truncation circle (area, normals, no gap at the hull), the damping profile,
// and the refusals with their numbers.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "forces/hydro/free_surface_mesh.hpp"
#include "forces/hydro/hull_shapes.hpp"
#include "forces/hydro/panel_geometry.hpp"
#include "forces/hydro/wetted_surface.hpp"

using namespace yardsim::forces::hydro;

namespace {

FreeSurfaceSettings settings() {
  FreeSurfaceSettings s;
  s.truncationRadius = 20.0;
  s.firstSpacing = 0.2;
  s.maxSpacing = 1.0;
  s.growth = 1.2;
  s.dampingWidth = 6.0;
  s.dampingStrength = 2.0;
  return s;
}

}  // namespace

TEST_CASE("the waterline of a hemisphere is one counter-clockwise loop on z = 0") {
  const PanelMesh wet = wettedSurface(cubeSphere(1.0, 8));
  const std::vector<int> loop = waterlineLoop(wet);
  REQUIRE(loop.size() == 32);  // 4 side faces x 8 divisions
  double area = 0.0;
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const Vector3& a = wet.vertices[static_cast<std::size_t>(loop[k])];
    const Vector3& b = wet.vertices[static_cast<std::size_t>(loop[(k + 1) % loop.size()])];
    CHECK(std::abs(a.z()) < 1e-12);
    CHECK(a.norm() == Approx(1.0).epsilon(1e-12));
    area += 0.5 * (a.x() * b.y() - b.x() * a.y());
  }
  // a 32-gon inscribed in the unit circle, counter-clockwise
  CHECK(area > 0.98 * std::numbers::pi);
  CHECK(area < std::numbers::pi);
}

TEST_CASE("free-surface rings cover the annulus from the waterline to the truncation circle") {
  const PanelMesh wet = wettedSurface(cubeSphere(1.0, 8));
  const FreeSurfaceMesh fs = buildFreeSurface(wet, settings());
  const std::vector<Panel> panels = buildPanels(fs.mesh);  // also checks orientation and shape
  REQUIRE(panels.size() == fs.damping.size());
  double area = 0.0, smallest = 1e9, largest = 0.0;
  for (const Panel& p : panels) {
    CHECK(p.normal.z() == Approx(-1.0).margin(1e-12));
    CHECK(std::abs(p.centroid.z()) < 1e-12);
    area += p.area;
    smallest = std::min(smallest, p.area);
    largest = std::max(largest, p.area);
  }
  // every ring is the waterline polygon (unit circle, the cube sphere's azimuths) scaled to its
  // radius, so the area is that polygon's times (R^2 - a^2)
  const std::vector<int> loop = waterlineLoop(wet);
  double polygon = 0.0;
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const Vector3& a = wet.vertices[static_cast<std::size_t>(loop[k])];
    const Vector3& b = wet.vertices[static_cast<std::size_t>(loop[(k + 1) % loop.size()])];
    polygon += 0.5 * (a.x() * b.y() - b.x() * a.y());
  }
  CHECK(area == Approx(polygon * (20.0 * 20.0 - 1.0)).epsilon(1e-9));
  // the first ring is the requested width (0.2 m, stretched by at most a ring's share)
  CHECK(smallest > 0.15 * 2.0 * std::numbers::pi / 32.0);
  CHECK(largest > smallest);
  // ring 0 is the waterline itself: no gap between hull and free surface
  for (std::size_t k = 0; k < loop.size(); ++k)
    CHECK((fs.mesh.vertices[k] - wet.vertices[static_cast<std::size_t>(loop[k])]).norm() == 0.0);
}

TEST_CASE(
    "the damping rises from zero at the inner edge of the zone to its strength at the truncation "
    "radius") {
  const FreeSurfaceMesh fs = buildFreeSurface(wettedSurface(cubeSphere(1.0, 8)), settings());
  const std::vector<Panel> panels = buildPanels(fs.mesh);
  double outer = 0.0;
  for (std::size_t k = 0; k < panels.size(); ++k) {
    const double r = panels[k].centroid.head<2>().norm();
    if (r < 14.0) CHECK(fs.damping[k] == 0.0);
    if (r > 14.0) {
      // (the profile is taken at the panel's vertex average, the check at its area centroid)
      const double x = (r - 14.0) / 6.0;
      CHECK(fs.damping[k] == Approx(2.0 * x * x).epsilon(0.05).margin(1e-3));
    }
    outer = std::max(outer, fs.damping[k]);
  }
  CHECK(outer > 0.8 * 2.0);
  CHECK(outer <= 2.0);
}

TEST_CASE("a hull reaching the truncation radius is refused with its numbers") {
  FreeSurfaceSettings s = settings();
  s.truncationRadius = 1.1;
  s.dampingWidth = 0.0;
  CHECK_THROWS_WITH(buildFreeSurface(wettedSurface(cubeSphere(1.0, 8)), s),
                    Catch::Contains("waterline radius 1.000000 m") &&
                        Catch::Contains("truncationRadius 1.100000 m"));
  s = settings();
  s.dampingWidth = 19.5;
  CHECK_THROWS_WITH(buildFreeSurface(wettedSurface(cubeSphere(1.0, 8)), s),
                    Catch::Contains("damping zone (19.500000 m wide) reaches the hull"));
}

TEST_CASE("a hull with no waterline is refused") {
  PanelMesh deep = cubeSphere(1.0, 4);
  for (Vector3& v : deep.vertices) v.z() -= 3.0;
  CHECK_THROWS_AS(waterlineLoop(wettedSurface(deep)), FreeSurfaceError);
}
