// Source strengths and field velocities: a translating sphere's flow field against the dipole
// phi = -a^3 U x / (2 r^3) off the body, its potential there, and the free-surface condition
// phi = 0 (no horizontal velocity on z = 0) with the image.
#include <catch2/catch.hpp>

#include <cmath>
#include <utility>

#include "forces/hydro/added_mass.hpp"
#include "forces/hydro/hull_shapes.hpp"
#include "forces/hydro/source_distribution.hpp"
#include "forces/hydro/wetted_surface.hpp"

using namespace yardsim::forces::hydro;

TEST_CASE("a translating sphere's field velocity converges to the dipole's") {
  // first order in the panel size (the source formulation; the potential formulation of the
  // added mass is second order): errors of a few per cent at these sizes, shrinking
  const double a = 1.0;
  const auto errors = [&](int n, const Vector3& x) {
    const std::vector<Panel> panels = buildPanels(cubeSphere(a, n));
    const SourceDistribution s(panels, FreeSurface::None, modeNormals(panels, Vector3::Zero()).col(0));
    const double r = x.norm();
    // grad(-a^3 x / (2 r^3)) = -a^3 / 2 (e_x / r^3 - 3 x x_vec / r^5)
    const Vector3 exact = -0.5 * a * a * a * (Vector3::UnitX() / (r * r * r) - 3.0 * x.x() * x / std::pow(r, 5));
    const double phi = -0.5 * a * a * a * x.x() / (r * r * r);
    return std::pair{(s.velocity(x) - exact).norm() / exact.norm(), std::abs(s.potential(x) / phi - 1.0)};
  };
  for (const Vector3& x : {Vector3(2.0, 0.5, 0.3), Vector3(-0.4, 1.6, -0.9)}) {
    const auto [u6, p6] = errors(6, x);
    const auto [u12, p12] = errors(12, x);
    CHECK(u12 < 0.04);
    CHECK(p12 < 0.04);
    CHECK(u6 / u12 > 1.3);
    CHECK(p6 / p12 > 1.3);
  }
}

TEST_CASE("with the negative image the free surface has phi = 0: no horizontal velocity on z = 0") {
  const std::vector<Panel> panels = buildPanels(wettedSurface(cubeSphere(1.0, 8)));
  const SourceDistribution s(panels, FreeSurface::NegativeImage, modeNormals(panels, Vector3::Zero()).col(2));
  for (const Vector3& x : {Vector3(1.5, 0.3, 0.0), Vector3(-2.0, 1.0, 0.0)}) {
    const Vector3 u = s.velocity(x);
    CHECK(std::abs(s.potential(x)) < 1e-12);
    CHECK(u.head<2>().norm() < 1e-12);
    CHECK(std::abs(u.z()) > 1e-3);  // the heaving hemisphere pushes the surface
  }
  // the normal velocity of heave is met at the collocation points: n . grad phi on the fluid side
  const Panel& p = panels[panels.size() / 2];
  const Vector3 x = p.centroid + 1e-6 * p.normal;
  CHECK(p.normal.dot(s.velocity(x)) == Approx(p.normal.z()).margin(2e-3));
}
