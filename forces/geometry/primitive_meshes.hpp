#pragma once
// Closed meshes of simple solids, generated in code (outward, watertight, shared vertices): for
// tests against closed forms, benchmarks of a given size, and simple hulls in scenes.
#include "forces/geometry/triangle_mesh.hpp"

namespace yardsim::forces {

// (size (x, y, z), m; divisions per edge along x, y, z) => a box centred on the origin, each face
// a grid of 2 n_a n_b triangles
TriangleMesh boxMesh(const dynamics::Vector3& size, int nx = 1, int ny = 1, int nz = 1);
// (radius, z of the bottom and of the top, m; segments around; rings along z) => a vertical
// cylinder on the z axis whose cross-section is the regular polygon inscribed in the circle, and
// fans for the end caps
TriangleMesh cylinderMesh(double radius, double zBottom, double zTop, int segments, int rings = 1);
// (radius, m; latitude bands, longitude segments) => a UV sphere centred on the origin with its
// vertices on the sphere (the inscribed polyhedron)
TriangleMesh sphereMesh(double radius, int bands, int segments);

}  // namespace yardsim::forces
