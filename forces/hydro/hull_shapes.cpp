#include "forces/hydro/hull_shapes.hpp"

#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>

namespace yardsim::forces::hydro {

namespace {

// Vertices merged by position (rounded to 1e-9 of the size), so that panels share their corners.
class VertexPool {
 public:
  VertexPool(PanelMesh& mesh, double size) : mesh_(mesh), scale_(1e9 / size) {}
  int at(const Vector3& x) {
    const std::array<long long, 3> key{std::llround(x.x() * scale_), std::llround(x.y() * scale_), std::llround(x.z() * scale_)};
    const auto [it, fresh] = index_.emplace(key, static_cast<int>(mesh_.vertices.size()));
    if (fresh) mesh_.vertices.push_back(x);
    return it->second;
  }

 private:
  PanelMesh& mesh_;
  double scale_;
  std::map<std::array<long long, 3>, int> index_;
};

}  // namespace

PanelMesh cubeSphere(double radius, int n) {
  if (!(radius > 0.0) || n < 1) throw std::invalid_argument("cubeSphere: radius must be > 0 and n >= 1");
  PanelMesh mesh;
  VertexPool pool(mesh, radius);
  // faces as (outward axis N, in-face axes U, V with U x V = N)
  const Vector3 X = Vector3::UnitX(), Y = Vector3::UnitY(), Z = Vector3::UnitZ();
  const std::array<std::array<Vector3, 3>, 6> faces{{{X, Y, Z}, {-X, Z, Y}, {Y, Z, X}, {-Y, X, Z}, {Z, X, Y}, {-Z, Y, X}}};
  // (face, i, j) => corner on the sphere at equal angles u, v in [-pi/4, pi/4]
  for (const auto& f : faces) {
    const auto corner = [&](int i, int j) {
      const double u = -std::numbers::pi / 4 + std::numbers::pi / 2 * i / n;
      const double v = -std::numbers::pi / 4 + std::numbers::pi / 2 * j / n;
      return pool.at(radius * (f[0] + std::tan(u) * f[1] + std::tan(v) * f[2]).normalized());
    };
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) mesh.addQuad(corner(i, j), corner(i + 1, j), corner(i + 1, j + 1), corner(i, j + 1));
    }
  }
  return mesh;
}

PanelMesh verticalCylinder(double radius, double zBottom, double zTop, int nAround, int nAxial, int nRadial) {
  if (!(radius > 0.0) || !(zTop > zBottom) || nAround < 3 || nAxial < 1 || nRadial < 1)
    throw std::invalid_argument("verticalCylinder: radius > 0, zTop > zBottom, nAround >= 3, nAxial >= 1, nRadial >= 1");
  PanelMesh mesh;
  VertexPool pool(mesh, radius + zTop - zBottom);
  // (ring r, angle index k, height z) => vertex
  const auto at = [&](double r, int k, double z) {
    const double t = 2.0 * std::numbers::pi * (k % nAround) / nAround;
    return pool.at(Vector3(r * std::cos(t), r * std::sin(t), z));
  };
  // side: first edge along +theta, second along +z => normal e_theta x e_z = e_r
  for (int l = 0; l < nAxial; ++l) {
    const double z0 = zBottom + (zTop - zBottom) * l / nAxial, z1 = zBottom + (zTop - zBottom) * (l + 1) / nAxial;
    for (int k = 0; k < nAround; ++k) mesh.addQuad(at(radius, k, z0), at(radius, k + 1, z0), at(radius, k + 1, z1), at(radius, k, z1));
  }
  // ends: a triangle fan round the axis, then quad rings; the bottom faces -z, the top +z
  for (const double z : {zBottom, zTop}) {
    const bool bottom = z == zBottom;
    const int c = pool.at(Vector3(0.0, 0.0, z));
    for (int k = 0; k < nAround; ++k) {
      const double r1 = radius / nRadial;
      if (bottom) mesh.addTriangle(c, at(r1, k + 1, z), at(r1, k, z));
      else mesh.addTriangle(c, at(r1, k, z), at(r1, k + 1, z));
    }
    for (int i = 1; i < nRadial; ++i) {
      const double r0 = radius * i / nRadial, r1 = radius * (i + 1) / nRadial;
      for (int k = 0; k < nAround; ++k) {
        if (bottom) mesh.addQuad(at(r0, k, z), at(r0, k + 1, z), at(r1, k + 1, z), at(r1, k, z));
        else mesh.addQuad(at(r0, k, z), at(r1, k, z), at(r1, k + 1, z), at(r0, k + 1, z));
      }
    }
  }
  return mesh;
}

}  // namespace yardsim::forces::hydro
