#include "forces/geometry/triangle_mesh.hpp"

#include <cstdint>
#include <map>
#include <numeric>
#include <sstream>
#include <unordered_map>

namespace yardsim::forces {

using dynamics::Matrix3;
using dynamics::Vector3;

namespace {

std::uint64_t edgeKey(int a, int b) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
         static_cast<std::uint32_t>(b);
}

std::string faceText(const TriangleMesh& m, std::size_t i) {
  const auto& t = m.triangles[i];
  std::ostringstream os;
  os << m.source << ": face " << i << " (vertices " << t[0] << ", " << t[1] << ", " << t[2] << ")";
  return os.str();
}

// union-find root with path halving
std::size_t root(std::vector<std::size_t>& parent, std::size_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

SolidProperties solidProperties(const TriangleMesh& mesh) {
  // (vertices) => a reference point inside the bounding box, to keep the sums well conditioned
  Vector3 o = Vector3::Zero();
  for (const Vector3& v : mesh.vertices) o += v;
  if (!mesh.vertices.empty()) o /= static_cast<double>(mesh.vertices.size());
  // (signed tetrahedra o, a, b, c) => volume, first and second moments about o
  double vol = 0.0;
  Vector3 first = Vector3::Zero();
  Matrix3 second = Matrix3::Zero();
  for (const auto& t : mesh.triangles) {
    const Vector3 a = mesh.vertices[static_cast<std::size_t>(t[0])] - o;
    const Vector3 b = mesh.vertices[static_cast<std::size_t>(t[1])] - o;
    const Vector3 c = mesh.vertices[static_cast<std::size_t>(t[2])] - o;
    const double d = a.dot(b.cross(c));
    const Vector3 s = a + b + c;
    vol += d / 6.0;
    first += d / 24.0 * s;
    second += d / 120.0 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
  }
  SolidProperties p;
  p.volume = vol;
  if (vol == 0.0) return p;
  const Vector3 g = first / vol;  // centroid relative to o
  p.centroid = o + g;
  // (second moment about o) => about the centroid, then the inertia tensor tr(C) 1 - C
  const Matrix3 C = second - vol * g * g.transpose();
  p.inertia = C.trace() * Matrix3::Identity() - C;
  return p;
}

void checkClosedMesh(const TriangleMesh& m, double areaTolerance) {
  if (m.triangles.empty()) throw MeshError(m.source + ": the mesh has no triangles");
  const int nv = static_cast<int>(m.vertices.size());
  // (vertices) => finite, and the bounding box for the degenerate-area scale
  Vector3 lo = Vector3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    if (!m.vertices[i].allFinite())
      throw MeshError(m.source + ": vertex " + std::to_string(i) + " is not finite");
    lo = lo.cwiseMin(m.vertices[i]);
    hi = hi.cwiseMax(m.vertices[i]);
  }
  const double minArea = areaTolerance * (hi - lo).squaredNorm();
  // (faces) => indices in range, distinct, area above the tolerance
  for (std::size_t i = 0; i < m.triangles.size(); ++i) {
    const auto& t = m.triangles[i];
    for (int k : t)
      if (k < 0 || k >= nv)
        throw MeshError(faceText(m, i) + ": vertex index " + std::to_string(k) +
                        " is outside the " + std::to_string(nv) + " vertices");
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
      throw MeshError(faceText(m, i) + ": a degenerate triangle (a vertex repeated)");
    if (areaVector(m, i).norm() <= minArea)
      throw MeshError(faceText(m, i) + ": a degenerate triangle (zero area)");
  }
  // (faces) => uses of every directed and undirected edge
  std::unordered_map<std::uint64_t, std::size_t> directed;        // (a, b) => first face
  std::unordered_map<std::uint64_t, int> undirected;              // (min, max) => uses
  directed.reserve(3 * m.triangles.size());
  undirected.reserve(3 * m.triangles.size());
  for (std::size_t i = 0; i < m.triangles.size(); ++i) {
    const auto& t = m.triangles[i];
    for (int e = 0; e < 3; ++e) {
      const int a = t[e], b = t[(e + 1) % 3];
      ++undirected[edgeKey(std::min(a, b), std::max(a, b))];
      const auto [it, fresh] = directed.emplace(edgeKey(a, b), i);
      if (!fresh)
        throw MeshError(faceText(m, i) + ": runs the edge " + std::to_string(a) + " -> " +
                        std::to_string(b) + " the same way as face " + std::to_string(it->second) +
                        ": inconsistent orientation (or more than two faces on one edge)");
    }
  }
  // (faces in order) => the first one with an edge no other face shares, or shared too often
  for (std::size_t i = 0; i < m.triangles.size(); ++i) {
    const auto& t = m.triangles[i];
    for (int e = 0; e < 3; ++e) {
      const int a = t[e], b = t[(e + 1) % 3];
      const int uses = undirected[edgeKey(std::min(a, b), std::max(a, b))];
      if (uses == 1)
        throw MeshError(faceText(m, i) + ": its edge " + std::to_string(a) + " - " +
                        std::to_string(b) + " belongs to no other face: the mesh is not closed "
                        "(watertight)");
      if (uses > 2)
        throw MeshError(faceText(m, i) + ": its edge " + std::to_string(a) + " - " +
                        std::to_string(b) + " is shared by " + std::to_string(uses) +
                        " faces: not a manifold");
    }
  }
  // (faces joined by edges) => connected parts, each of positive volume (faces point outward)
  std::vector<std::size_t> parent(m.triangles.size());
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  for (std::size_t i = 0; i < m.triangles.size(); ++i) {
    const auto& t = m.triangles[i];
    for (int e = 0; e < 3; ++e) {
      const std::size_t j = directed.at(edgeKey(t[(e + 1) % 3], t[e]));  // the neighbour
      parent[root(parent, i)] = root(parent, j);
    }
  }
  std::map<std::size_t, std::pair<double, std::size_t>> parts;  // root => (volume, first face)
  const Vector3 o = 0.5 * (lo + hi);
  for (std::size_t i = 0; i < m.triangles.size(); ++i) {
    const auto& t = m.triangles[i];
    const Vector3 a = m.vertices[static_cast<std::size_t>(t[0])] - o;
    const Vector3 b = m.vertices[static_cast<std::size_t>(t[1])] - o;
    const Vector3 c = m.vertices[static_cast<std::size_t>(t[2])] - o;
    auto [it, fresh] = parts.emplace(root(parent, i), std::make_pair(0.0, i));
    it->second.first += a.dot(b.cross(c)) / 6.0;
  }
  for (const auto& [r, part] : parts)
    if (part.first <= 0.0)
      throw MeshError(faceText(m, part.second) + ": the closed part containing this face has volume " +
                      std::to_string(part.first) +
                      " m^3: its faces point inward (reverse the vertex order of every face)");
}

TriangleMesh transformed(const TriangleMesh& mesh, const dynamics::Transform& X_AB, double scale) {
  TriangleMesh out = mesh;
  for (Vector3& v : out.vertices) v = X_AB.actPoint(scale * v);
  return out;
}

TriangleMesh weldVertices(const TriangleMesh& mesh) {
  TriangleMesh out;
  out.source = mesh.source;
  std::map<std::array<double, 3>, int> index;
  std::vector<int> remap(mesh.vertices.size(), -1);
  // (triangles in order) => every used vertex once, first use first
  out.triangles.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    std::array<int, 3> u{};
    for (int k = 0; k < 3; ++k) {
      const auto vi = static_cast<std::size_t>(t[static_cast<std::size_t>(k)]);
      if (remap[vi] < 0) {
        const Vector3& v = mesh.vertices[vi];
        const auto [it, fresh] = index.emplace(std::array<double, 3>{v.x(), v.y(), v.z()},
                                               static_cast<int>(out.vertices.size()));
        if (fresh) out.vertices.push_back(v);
        remap[vi] = it->second;
      }
      u[static_cast<std::size_t>(k)] = remap[vi];
    }
    out.triangles.push_back(u);
  }
  return out;
}

}  // namespace yardsim::forces
