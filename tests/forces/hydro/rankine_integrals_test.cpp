// The exact panel integrals against closed forms (a square's self-influence, the solid angle of a
// closed surface) and against brute-force Gauss quadrature; the one-point rule's switch distance
// and error order; the source gradient against finite differences of the source integral.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "forces/hydro/hull_shapes.hpp"
#include "forces/hydro/rankine_integrals.hpp"

using namespace yardsim::forces::hydro;

namespace {

// A flat quad panel of side s in the plane z = 0, centred at the origin, normal +z.
Panel square(double s) {
  PanelMesh m;
  m.vertices = {{-s / 2, -s / 2, 0}, {s / 2, -s / 2, 0}, {s / 2, s / 2, 0}, {-s / 2, s / 2, 0}};
  m.addQuad(0, 1, 2, 3);
  return buildPanels(m)[0];
}

// A tilted, irregular quad.
Panel skewQuad() {
  PanelMesh m;
  m.vertices = {{0.0, 0.0, 0.0}, {1.3, 0.1, 0.2}, {1.1, 0.9, 0.5}, {-0.2, 0.7, 0.25}};
  m.addQuad(0, 1, 2, 3);
  return buildPanels(m)[0];
}

// (panel, x) => S and D by a 64 x 64 Gauss-Legendre rule on each fan triangle (collapsed square)
PanelIntegrals quadrature(const Panel& p, const Vector3& x) {
  constexpr int n = 64;
  double gx[n], gw[n];
  // Gauss-Legendre nodes on [0, 1] by Newton on P_n
  for (int i = 0; i < n; ++i) {
    double t = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5)), dp = 0.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = t;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * t * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (t * p1 - p0) / (t * t - 1.0);
      const double dt = p1 / dp;
      t -= dt;
      if (std::abs(dt) < 1e-15) break;
    }
    gx[i] = 0.5 * (1.0 - t);
    gw[i] = 1.0 / ((1.0 - t * t) * dp * dp) * 2.0 * 0.5;
  }
  PanelIntegrals r;
  for (int j = 1; j + 1 < p.count; ++j) {
    const Vector3 a = p.vertices[0], b = p.vertices[static_cast<std::size_t>(j)], c = p.vertices[static_cast<std::size_t>(j + 1)];
    const double twiceArea = (b - a).cross(c - a).norm();
    for (int i = 0; i < n; ++i) {
      for (int k = 0; k < n; ++k) {
        // (u, v) in the unit square => point u (1 - v) on edge ab-ac, Jacobian u
        const double u = gx[i], v = gx[k];
        const Vector3 q = a + u * ((1 - v) * (b - a) + v * (c - a));
        const double w = gw[i] * gw[k] * u * twiceArea;
        const Vector3 d = x - q;
        const double rr = d.norm();
        r.source += w / rr;
        r.dipole += w * p.normal.dot(d) / (rr * rr * rr);
      }
    }
  }
  return r;
}

}  // namespace

TEST_CASE("the self-influence of a flat square at its centre is 4 s ln(1 + sqrt 2)") {
  for (const double s : {1.0, 0.37, 12.0}) {
    const Panel p = square(s);
    const PanelIntegrals v = exactIntegrals(p, p.centroid);
    CHECK(v.source == Approx(4.0 * s * std::log(1.0 + std::sqrt(2.0))).epsilon(1e-13));
    CHECK(v.dipole == 0.0);
  }
}

TEST_CASE("exact integrals agree with brute-force quadrature off the panel") {
  const Panel p = skewQuad();
  const Vector3 n = p.normal;
  for (const Vector3& x : {Vector3(p.centroid + 0.4 * n), Vector3(p.centroid - 0.25 * n + Vector3(0.3, 0.1, 0.0)),
                           Vector3(2.0, 1.5, -0.7), Vector3(0.5, 0.4, 1.5), Vector3(p.vertices[1] + 0.6 * n)}) {
    const PanelIntegrals e = exactIntegrals(p, x);
    const PanelIntegrals q = quadrature(p, x);
    CHECK(e.source == Approx(q.source).epsilon(1e-7));
    CHECK(e.dipole == Approx(q.dipole).epsilon(1e-6).margin(1e-9));
  }
}

TEST_CASE("the solid angle of a closed faceted surface is 4 pi from inside and 0 from outside") {
  // sum of D = -(solid angle) for outward normals
  // the cube sphere's quads split into triangles: a closed polyhedron (its quads, projected on
  // their mean planes, would leave slits between them)
  PanelMesh sphere = cubeSphere(2.0, 5), triangles;
  triangles.vertices = sphere.vertices;
  for (const auto& q : sphere.panels) {
    triangles.addTriangle(q[0], q[1], q[2]);
    triangles.addTriangle(q[0], q[2], q[3]);
  }
  for (const PanelMesh& m : {triangles, verticalCylinder(1.0, -2.0, 0.5, 12, 4, 3)}) {
    const std::vector<Panel> panels = buildPanels(m);
    const auto omega = [&](const Vector3& x) {
      double s = 0.0;
      for (const Panel& p : panels) s -= exactIntegrals(p, x).dipole;
      return s;
    };
    for (const Vector3& inside : {Vector3(0.0, 0.0, -0.5), Vector3(0.3, -0.2, 0.1), Vector3(0.0, 0.8, -1.6)})
      CHECK(omega(inside) == Approx(4.0 * std::numbers::pi).epsilon(1e-12));
    for (const Vector3& outside : {Vector3(0.0, 0.0, 2.3), Vector3(1.5, 1.5, -1.0), Vector3(40.0, -3.0, 7.0)})
      CHECK(omega(outside) == Approx(0.0).margin(1e-12));
  }
}

TEST_CASE("the one-point rule takes over beyond four panel diameters with an error of order (d/R)^2") {
  const Panel p = skewQuad();
  const Vector3 dir = Vector3(0.6, -0.3, 0.74).normalized();
  // (distance in diameters) => error of the one-point rule, scaled by A/R (source) and A/R^2 (dipole)
  const auto errors = [&](double k) {
    const Vector3 x = p.centroid + k * p.diameter * dir;
    const double R = k * p.diameter;
    const PanelIntegrals e = exactIntegrals(p, x), o = onePointIntegrals(p, x);
    return std::pair{std::abs(e.source - o.source) / (p.area / R), std::abs(e.dipole - o.dipole) / (p.area / (R * R))};
  };
  // the switch: exact just inside, one-point just outside
  const Vector3 in = p.centroid + 0.999 * kFarField * p.diameter * dir;
  const Vector3 out = p.centroid + 1.001 * kFarField * p.diameter * dir;
  CHECK_FALSE(isFarField(p, in));
  CHECK(isFarField(p, out));
  CHECK(panelIntegrals(p, in).source == exactIntegrals(p, in).source);
  CHECK(panelIntegrals(p, out).source == onePointIntegrals(p, out).source);
  CHECK(panelIntegrals(p, out).dipole == onePointIntegrals(p, out).dipole);
  // the error at the switch is small, and falls by ~4 per doubling of the distance
  const auto [s4, d4] = errors(kFarField);
  const auto [s8, d8] = errors(2.0 * kFarField);
  const auto [s16, d16] = errors(4.0 * kFarField);
  CHECK(s4 < 1e-3);
  CHECK(d4 < 5e-3);
  CHECK(s8 < s4);
  CHECK(d8 < d4);
  CHECK(std::log2(s8 / s16) == Approx(2.0).margin(0.2));
  CHECK(std::log2(d8 / d16) == Approx(2.0).margin(0.2));
}

TEST_CASE("the source gradient is the derivative of the source integral") {
  const Panel p = skewQuad();
  for (const Vector3& x : {Vector3(p.centroid + 0.3 * p.normal), Vector3(1.8, -0.4, 0.9), Vector3(p.centroid + 7.0 * p.normal)}) {
    const double h = 1e-5;
    Vector3 fd;
    for (int k = 0; k < 3; ++k) {
      const Vector3 e = h * Vector3::Unit(k);
      fd[k] = (panelIntegrals(p, x + e).source - panelIntegrals(p, x - e).source) / (2 * h);
    }
    CHECK((sourceGradient(p, x) - fd).norm() < 1e-7 * fd.norm() + 1e-9);
  }
}
