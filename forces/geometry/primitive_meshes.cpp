#include "forces/geometry/primitive_meshes.hpp"

#include <cmath>
#include <stdexcept>

namespace yardsim::forces {

using dynamics::Vector3;

namespace {
// (lo, hi, i of n) => the grid coordinate, computed the same way on every face (exact welding)
double grid(double lo, double hi, int i, int n) {
  return i == n ? hi : lo + (hi - lo) * static_cast<double>(i) / static_cast<double>(n);
}
}  // namespace

TriangleMesh boxMesh(const Vector3& size, int nx, int ny, int nz) {
  if (!(size.minCoeff() > 0) || nx < 1 || ny < 1 || nz < 1)
    throw std::invalid_argument("boxMesh: the size must be > 0 and the divisions >= 1");
  TriangleMesh m;
  m.source = "box mesh";
  const Vector3 lo = -0.5 * size, hi = 0.5 * size;
  const int n[3] = {nx, ny, nz};
  // (each axis a, each side) => a grid on the face normal to a, wound so its normal points out
  for (int a = 0; a < 3; ++a) {
    const int u = (a + 1) % 3, v = (a + 2) % 3;  // (u, v, a) right-handed
    for (int side = 0; side < 2; ++side) {
      const int base = static_cast<int>(m.vertices.size());
      for (int j = 0; j <= n[v]; ++j)
        for (int i = 0; i <= n[u]; ++i) {
          Vector3 p;
          p[a] = side ? hi[a] : lo[a];
          p[u] = grid(lo[u], hi[u], i, n[u]);
          p[v] = grid(lo[v], hi[v], j, n[v]);
          m.vertices.push_back(p);
        }
      auto at = [&](int i, int j) { return base + j * (n[u] + 1) + i; };
      for (int j = 0; j < n[v]; ++j)
        for (int i = 0; i < n[u]; ++i) {
          const int a0 = at(i, j), a1 = at(i + 1, j), a2 = at(i + 1, j + 1), a3 = at(i, j + 1);
          if (side) {  // normal +a = u x v: counter-clockwise in (u, v)
            m.triangles.push_back({a0, a1, a2});
            m.triangles.push_back({a0, a2, a3});
          } else {
            m.triangles.push_back({a0, a2, a1});
            m.triangles.push_back({a0, a3, a2});
          }
        }
    }
  }
  TriangleMesh w = weldVertices(m);
  w.source = m.source;
  return w;
}

TriangleMesh cylinderMesh(double radius, double zBottom, double zTop, int segments, int rings) {
  if (!(radius > 0) || !(zTop > zBottom) || segments < 3 || rings < 1)
    throw std::invalid_argument("cylinderMesh: radius > 0, top above bottom, >= 3 segments, >= 1 ring");
  TriangleMesh m;
  m.source = "cylinder mesh";
  // (rings + 1 circles of `segments` vertices, then the two cap centres) => vertices
  for (int r = 0; r <= rings; ++r) {
    const double z = grid(zBottom, zTop, r, rings);
    for (int s = 0; s < segments; ++s) {
      const double a = 2.0 * M_PI * s / segments;
      m.vertices.emplace_back(radius * std::cos(a), radius * std::sin(a), z);
    }
  }
  const int bottom = static_cast<int>(m.vertices.size());
  m.vertices.emplace_back(0.0, 0.0, zBottom);
  m.vertices.emplace_back(0.0, 0.0, zTop);
  const int top = bottom + 1;
  auto at = [&](int r, int s) { return r * segments + (s % segments); };
  for (int s = 0; s < segments; ++s) {
    for (int r = 0; r < rings; ++r) {  // sides: counter-clockwise seen from outside
      m.triangles.push_back({at(r, s), at(r, s + 1), at(r + 1, s + 1)});
      m.triangles.push_back({at(r, s), at(r + 1, s + 1), at(r + 1, s)});
    }
    m.triangles.push_back({bottom, at(0, s + 1), at(0, s)});        // normal -z
    m.triangles.push_back({top, at(rings, s), at(rings, s + 1)});  // normal +z
  }
  return m;
}

TriangleMesh sphereMesh(double radius, int bands, int segments) {
  if (!(radius > 0) || bands < 2 || segments < 3)
    throw std::invalid_argument("sphereMesh: radius > 0, >= 2 bands, >= 3 segments");
  TriangleMesh m;
  m.source = "sphere mesh";
  // (south pole, bands - 1 rings, north pole) => vertices
  m.vertices.emplace_back(0.0, 0.0, -radius);
  for (int b = 1; b < bands; ++b) {
    const double polar = M_PI * b / bands;  // from the south pole
    for (int s = 0; s < segments; ++s) {
      const double a = 2.0 * M_PI * s / segments;
      m.vertices.emplace_back(radius * std::sin(polar) * std::cos(a),
                              radius * std::sin(polar) * std::sin(a), -radius * std::cos(polar));
    }
  }
  const int north = static_cast<int>(m.vertices.size());
  m.vertices.emplace_back(0.0, 0.0, radius);
  auto at = [&](int ring, int s) { return 1 + ring * segments + (s % segments); };
  for (int s = 0; s < segments; ++s) {
    m.triangles.push_back({0, at(0, s + 1), at(0, s)});
    for (int r = 0; r + 1 < bands - 1; ++r) {
      m.triangles.push_back({at(r, s), at(r, s + 1), at(r + 1, s + 1)});
      m.triangles.push_back({at(r, s), at(r + 1, s + 1), at(r + 1, s)});
    }
    m.triangles.push_back({north, at(bands - 2, s), at(bands - 2, s + 1)});
  }
  return m;
}

}  // namespace yardsim::forces
