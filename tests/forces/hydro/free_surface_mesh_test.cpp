// Free-surface panels round a floating hemisphere: the waterline loop, the rings from the
// waterline to the truncation circle (area, normals, no gap at the hull), the damping profile,
// and the refusals with their numbers.
#include <catch2/catch.hpp>

#include <array>
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

namespace {

// (a hemisphere stretched 3 times along x) => an elongated waterline: the rays fan unevenly
PanelMesh elongatedHull() {
  PanelMesh hull = cubeSphere(1.0, 8);
  for (Vector3& v : hull.vertices) v.x() *= 3.0;
  return wettedSurface(hull);
}

// (panel, point on z = 0) => whether the point lies inside the panel seen from above (the
// corners turn clockwise seen from above, normals -z)
bool contains(const PanelMesh& mesh, const std::array<int, 4>& ix, double x, double y) {
  const int n = ix[3] < 0 ? 3 : 4;
  for (int j = 0; j < n; ++j) {
    const Vector3& a = mesh.vertices[static_cast<std::size_t>(ix[static_cast<std::size_t>(j)])];
    const Vector3& b =
        mesh.vertices[static_cast<std::size_t>(ix[static_cast<std::size_t>((j + 1) % n)])];
    if ((b.x() - a.x()) * (y - a.y()) - (b.y() - a.y()) * (x - a.x()) > 0.0) return false;
  }
  return true;
}

// (mesh, panel) => its longer edge along the rings: corners 0-1 and 2-3 (a a1 b1 b)
double ringEdge(const PanelMesh& mesh, const std::array<int, 4>& ix) {
  const auto v = [&](int j) -> const Vector3& {
    return mesh.vertices[static_cast<std::size_t>(ix[static_cast<std::size_t>(j)])];
  };
  return std::max((v(1) - v(0)).norm(), (v(3) - v(2)).norm());
}

// (mesh, panel) => its longer edge along the rays: corners 0-3 and 1-2
double rayEdge(const PanelMesh& mesh, const std::array<int, 4>& ix) {
  const auto v = [&](int j) -> const Vector3& {
    return mesh.vertices[static_cast<std::size_t>(ix[static_cast<std::size_t>(j)])];
  };
  return std::max((v(3) - v(0)).norm(), (v(2) - v(1)).norm());
}

// (mesh, panel) => the largest distance of a corner from the z axis
double outerRadius(const PanelMesh& mesh, const std::array<int, 4>& ix) {
  double r = 0.0;
  for (const int i : ix)
    r = std::max(r, mesh.vertices[static_cast<std::size_t>(i)].head<2>().norm());
  return r;
}

}  // namespace

TEST_CASE("without refinement the rings are the rays' mesh: one vertex per ray and ring") {
  const PanelMesh wet = elongatedHull();
  const FreeSurfaceMesh fs = buildFreeSurface(wet, settings());
  const auto nw = waterlineLoop(wet).size();
  REQUIRE(fs.mesh.panels.size() % nw == 0);
  CHECK(fs.mesh.vertices.size() == fs.mesh.panels.size() + nw);
}

TEST_CASE(
    "azimuthal refinement splits the panels wide along the rings and covers the same annulus "
    "once") {
  const PanelMesh wet = elongatedHull();
  FreeSurfaceSettings s = settings();
  const FreeSurfaceMesh plain = buildFreeSurface(wet, s);
  s.azimuthSpacing = 0.5;
  const FreeSurfaceMesh fine = buildFreeSurface(wet, s);
  REQUIRE(fine.mesh.panels.size() == fine.damping.size());
  CHECK(fine.mesh.panels.size() > 2 * plain.mesh.panels.size());
  // (area) => the split panels cover exactly the unsplit ones
  double plainArea = 0.0, fineArea = 0.0;
  for (const Panel& p : buildPanels(plain.mesh)) plainArea += p.area;
  for (const Panel& p : buildPanels(fine.mesh)) fineArea += p.area;  // also orientation, shape
  CHECK(fineArea == Approx(plainArea).epsilon(1e-12));
  // (inside the zone's inner edge, 14 m) => no edge along the rings above 0.5 m; unrefined: many
  int plainWide = 0, fineWide = 0, fineInner = 0;
  for (const auto& ix : plain.mesh.panels)
    if (outerRadius(plain.mesh, ix) < 14.0 && ringEdge(plain.mesh, ix) > 0.5) ++plainWide;
  for (const auto& ix : fine.mesh.panels) {
    if (outerRadius(fine.mesh, ix) >= 14.0) continue;
    ++fineInner;
    if (ringEdge(fine.mesh, ix) > 0.5 + 1e-12) ++fineWide;
  }
  CHECK(plainWide > 100);
  CHECK(fineInner > 1000);
  CHECK(fineWide == 0);
  // (points on a grid between the hull and the outer polygon) => inside exactly one panel: no
  // gap and no overlap where a row's split differs from its neighbour's (hanging corners)
  double rOuter = 20.0;  // (the outer polygon's edges) => the largest circle inside it
  for (const auto& ix : plain.mesh.panels) {
    const Vector3& b1 = plain.mesh.vertices[static_cast<std::size_t>(ix[2])];
    const Vector3& b = plain.mesh.vertices[static_cast<std::size_t>(ix[3])];
    if (b.norm() > 19.99 && b1.norm() > 19.99)
      rOuter = std::min(rOuter, std::abs(b.x() * b1.y() - b.y() * b1.x()) / (b1 - b).norm());
  }
  int points = 0, wrong = 0;
  for (double x = -19.93; x < 20.0; x += 0.391) {
    for (double y = -19.87; y < 20.0; y += 0.373) {
      if (std::hypot(x, y) > rOuter - 0.01 || std::hypot(x / 3.0, y) < 1.01) continue;
      int inside = 0;
      for (const auto& ix : fine.mesh.panels) inside += contains(fine.mesh, ix, x, y) ? 1 : 0;
      ++points;
      if (inside != 1) ++wrong;
    }
  }
  CHECK(points > 5000);
  CHECK(wrong == 0);
}

TEST_CASE("the beach spacing widens the rings inside the damping zone only") {
  const PanelMesh wet = elongatedHull();
  FreeSurfaceSettings s = settings();  // rings up to 1 m, zone from 14 m
  s.beachSpacing = 2.5;
  s.azimuthSpacing = 0.5;
  const FreeSurfaceMesh fs = buildFreeSurface(wet, s);
  double innerRay = 0.0, innerRing = 0.0, zoneRay = 0.0, zoneRing = 0.0;
  for (const auto& ix : fs.mesh.panels) {
    double rMin = 1e9;
    for (const int i : ix)
      rMin = std::min(rMin, fs.mesh.vertices[static_cast<std::size_t>(i)].head<2>().norm());
    if (outerRadius(fs.mesh, ix) < 14.0) {
      innerRay = std::max(innerRay, rayEdge(fs.mesh, ix));
      innerRing = std::max(innerRing, ringEdge(fs.mesh, ix));
    }
    if (rMin > 14.0) {
      zoneRay = std::max(zoneRay, rayEdge(fs.mesh, ix));
      zoneRing = std::max(zoneRing, ringEdge(fs.mesh, ix));
    }
  }
  // (rays stretched by (R - r_k) / (R - r_mean) and the rings by the last one's fit) => 1 m, 2.5 m
  CHECK(innerRay < 1.0 * 1.25);
  CHECK(innerRing < 0.5 + 1e-12);
  CHECK(zoneRay > 1.6);
  CHECK(zoneRay < 2.5 * 1.25);
  CHECK(zoneRing < 2.5 + 1e-12);
  CHECK(zoneRing > 1.25);
}

TEST_CASE("spacings that ask for more panels than the dense solver holds are refused first") {
  const PanelMesh wet = elongatedHull();
  FreeSurfaceSettings s = settings();
  s.azimuthSpacing = 1e-6;  // (a typo for 1 m) => about 2^20 parts per ray
  CHECK_THROWS_WITH(buildFreeSurface(wet, s), Catch::Contains("panels, more than 20000") &&
                                                  Catch::Contains("azimuthSpacing"));
  s = settings();
  s.firstSpacing = s.maxSpacing = 1e-9;
  CHECK_THROWS_WITH(buildFreeSurface(wet, s), Catch::Contains("rings of") &&
                                                  Catch::Contains("raise maxSpacing"));
  s = settings();
  s.azimuthSpacing = 0.2;  // (within the limit) => built
  CHECK(buildFreeSurface(wet, s).mesh.panels.size() <= 20000);
}
