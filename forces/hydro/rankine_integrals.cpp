#include "forces/hydro/rankine_integrals.hpp"

#include <cmath>

namespace yardsim::forces::hydro {

namespace {

// (panel, x) => D by van Oosterom & Strackee over the fan triangles from corner 0
double exactDipole(const Panel& p, const Vector3& x) {
  const double z = p.normal.dot(x - p.centroid);
  if (std::abs(z) <= 1e-12 * p.diameter) return 0.0;
  const Vector3 r0 = p.vertices[0] - x;
  const double n0 = r0.norm();
  double omega = 0.0;
  for (int j = 1; j + 1 < p.count; ++j) {
    const Vector3 r1 = p.vertices[static_cast<std::size_t>(j)] - x;
    const Vector3 r2 = p.vertices[static_cast<std::size_t>(j + 1)] - x;
    const double n1 = r1.norm(), n2 = r2.norm();
    const double num = r0.dot(r1.cross(r2));
    const double den = n0 * n1 * n2 + r0.dot(r1) * n2 + r0.dot(r2) * n1 + r1.dot(r2) * n0;
    omega += 2.0 * std::atan2(num, den);
  }
  return -omega;
}

// (edge ends' distances ra, rb, length d) => ln((ra + rb + d) / (ra + rb - d)), 0 on the edge
// itself (where its factor p_k vanishes)
double edgeLog(double ra, double rb, double d) {
  const double s = ra + rb;
  const double den = s - d;
  if (den <= 1e-14 * s) return 0.0;
  return std::log((s + d) / den);
}

}  // namespace

PanelIntegrals exactIntegrals(const Panel& p, const Vector3& x) {
  // (corners, x) => D, then S = sum_k p_k L_k - Z D
  PanelIntegrals r;
  r.dipole = exactDipole(p, x);
  double s = 0.0;
  for (int k = 0; k < p.count; ++k) {
    const Vector3& a = p.vertices[static_cast<std::size_t>(k)];
    const Vector3& b = p.vertices[static_cast<std::size_t>((k + 1) % p.count)];
    const Vector3 e = b - a;
    const double d = e.norm();
    const double pk = (x - a).dot(p.normal.cross(e)) / d;
    if (pk == 0.0) continue;
    s += pk * edgeLog((x - a).norm(), (x - b).norm(), d);
  }
  r.source = s - p.normal.dot(x - p.centroid) * r.dipole;
  return r;
}

PanelIntegrals onePointIntegrals(const Panel& p, const Vector3& x) {
  // (A, c, n, x) => A / R, A n.(x - c) / R^3
  const Vector3 rv = x - p.centroid;
  const double r2 = rv.squaredNorm();
  const double r = std::sqrt(r2);
  return {p.area / r, p.area * p.normal.dot(rv) / (r2 * r)};
}

Vector3 sourceGradient(const Panel& p, const Vector3& x) {
  if (isFarField(p, x)) {
    // (A, c, x) => -A (x - c) / R^3
    const Vector3 rv = x - p.centroid;
    const double r = rv.norm();
    return -p.area * rv / (r * r * r);
  }
  // (edges, x) => sum_k (n x t_k) L_k - n D
  Vector3 g = -exactDipole(p, x) * p.normal;
  for (int k = 0; k < p.count; ++k) {
    const Vector3& a = p.vertices[static_cast<std::size_t>(k)];
    const Vector3& b = p.vertices[static_cast<std::size_t>((k + 1) % p.count)];
    const Vector3 e = b - a;
    const double d = e.norm();
    g += p.normal.cross(e / d) * edgeLog((x - a).norm(), (x - b).norm(), d);
  }
  return g;
}

}  // namespace yardsim::forces::hydro
