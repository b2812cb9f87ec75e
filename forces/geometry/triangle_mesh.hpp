#pragma once
// A closed triangulated surface (a hull, a pontoon, a block): shared vertices and triangles whose
// corners run counter-clockwise seen from outside (right-hand rule: (b - a) x (c - a) points out).
// Used by hydrostatics (clipping at the water surface), and by anything else that needs the
// enclosed solid (panel methods, inertia of a hull). The checks refuse what the clipping cannot
// use: an open surface, a triangle turned the wrong way, a degenerate triangle, a solid of
// negative volume; the error names the source (file) and the first offending face (0-based).
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include "dynamics/spatial.hpp"

namespace yardsim::forces {

struct TriangleMesh {
  std::vector<dynamics::Vector3> vertices;  // m, in the mesh (body) frame
  std::vector<std::array<int, 3>> triangles;  // vertex indices, counter-clockwise from outside
  std::string source;                         // file name or a description, for errors
};

// A mesh that fails a check or a file that cannot be read; the message names the source and,
// where there is one, the first offending face (or line of the file).
class MeshError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Volume, centroid and inertia of the solid enclosed by a closed mesh at unit density
// (divergence theorem: signed tetrahedra from the origin to each triangle).
struct SolidProperties {
  double volume = 0.0;                                     // m^3
  dynamics::Vector3 centroid = dynamics::Vector3::Zero();  // m, mesh frame
  dynamics::Matrix3 inertia = dynamics::Matrix3::Zero();   // m^5: about the centroid, per kg/m^3
};

// (mesh) => its solid's volume, centroid and inertia about the centroid at density 1 kg/m^3
// (multiply the inertia by the density, or by mass / volume). No checks: a mesh that is not
// closed gives meaningless numbers, call checkClosedMesh first.
SolidProperties solidProperties(const TriangleMesh& mesh);

// (mesh, relative area tolerance) => nothing, or MeshError naming mesh.source and the first
// offending face: a vertex index out of range or repeated; a degenerate triangle (area below
// tolerance x (bounding-box diagonal)^2); an edge used by one face only (not watertight) or by
// more than two (not a manifold); two neighbours that run an edge the same way (inconsistent
// orientation); a connected part of negative volume (turned inside out: faces point inward).
void checkClosedMesh(const TriangleMesh& mesh, double areaTolerance = 1e-12);

// (mesh) => the area vector (b - a) x (c - a) / 2 of triangle i: outward normal times area, m^2
inline dynamics::Vector3 areaVector(const TriangleMesh& mesh, std::size_t i) {
  const auto& t = mesh.triangles[i];
  const dynamics::Vector3& a = mesh.vertices[static_cast<std::size_t>(t[0])];
  return 0.5 * (mesh.vertices[static_cast<std::size_t>(t[1])] - a)
                   .cross(mesh.vertices[static_cast<std::size_t>(t[2])] - a);
}

// (mesh, X_AB mapping mesh frame B into A, uniform scale applied first) => the mesh in frame A
TriangleMesh transformed(const TriangleMesh& mesh, const dynamics::Transform& X_AB, double scale = 1.0);

// (mesh) => the same surface with exactly coincident vertices merged (STL stores every triangle
// with its own three corners); unused vertices dropped
TriangleMesh weldVertices(const TriangleMesh& mesh);

}  // namespace yardsim::forces
