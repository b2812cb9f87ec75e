// The wetted part of a hull: a sphere cut at its centre plane is a hemisphere (area, water-plane
// edge at z = 0, still consistently oriented), a cylinder cut between two rows keeps the wetted
// side area, and a hull wholly above water leaves nothing.
#include <catch2/catch.hpp>

#include <numbers>

#include "forces/hydro/hull_shapes.hpp"
#include "forces/hydro/panel_geometry.hpp"
#include "forces/hydro/wetted_surface.hpp"

using namespace yardsim::forces::hydro;

namespace {

double area(const std::vector<Panel>& ps) {
  double a = 0.0;
  for (const Panel& p : ps) a += p.area;
  return a;
}

}  // namespace

TEST_CASE("a cube sphere cut at z = 0 keeps its lower half") {
  const PanelMesh sphere = cubeSphere(1.0, 8);
  const PanelMesh wet = wettedSurface(sphere);
  CHECK(wet.panelCount() == 3 * 64);
  const std::vector<Panel> ps = buildPanels(wet);  // consistent orientation survives the cut
  CHECK(area(ps) == Approx(0.5 * area(buildPanels(sphere))).epsilon(1e-12));
  for (const Vector3& v : wet.vertices) CHECK(v.z() <= 1e-15);
}

TEST_CASE("a cylinder cut between two rows of vertices") {
  // rows at z = -2, -1, 0, 1 cut at z = -0.5 after shifting the hull up by 0.5
  PanelMesh hull = verticalCylinder(1.0, -1.5, 1.5, 16, 3, 2);
  const PanelMesh wet = wettedSurface(hull);
  const std::vector<Panel> ps = buildPanels(wet);
  double side = 0.0, bottom = 0.0;
  for (const Panel& p : ps) (std::abs(p.normal.z()) < 1e-12 ? side : bottom) += p.area;
  const double perimeter = 16 * 2 * std::sin(std::numbers::pi / 16);
  CHECK(side == Approx(perimeter * 1.5));
  CHECK(bottom == Approx(0.5 * 16 * std::sin(2 * std::numbers::pi / 16)));
  for (const Vector3& v : wet.vertices) CHECK(v.z() <= 0.0);
}

TEST_CASE("a hull above the water has no wetted surface") {
  PanelMesh hull = verticalCylinder(1.0, 0.2, 1.0, 8, 2, 2);
  CHECK(wettedSurface(hull).panelCount() == 0);
}
