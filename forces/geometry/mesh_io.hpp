#pragma once
// Reading and writing triangle meshes: Wavefront OBJ (v and f records; polygons fanned into
// triangles; other records ignored) and STL (binary and ASCII, told apart by the file size).
// Our own small readers: the formats are tiny, and a reader of our own gives errors with the
// file and line and welds STL's per-triangle corners into shared vertices, which the checks and
// the clipping need. Errors: MeshError naming the file (and the line for text formats).
#include <cstdint>
#include <string>

#include "forces/geometry/triangle_mesh.hpp"

namespace yardsim::forces {

// A mesh file read by readMesh has at most this many bytes (256 MiB: a binary STL of about 5
// million triangles); a larger file is refused before it is read.
inline constexpr std::uintmax_t kMaxMeshFileBytes = std::uintmax_t{256} << 20;
// (path) => the mesh, by extension (.obj, .stl, .step/.stp through readStep with its default
// tolerance; any case); source = path. Throws MeshError, also for a path that is not a regular
// file (a device or a FIFO would never end) or is larger than kMaxMeshFileBytes.
TriangleMesh readMesh(const std::string& path);
// (path) => readMesh(path), then checkClosedMesh: a hull ready for clipping
TriangleMesh readClosedMesh(const std::string& path);
// (path) => vertices and faces of an OBJ file (1-based and negative indices, v/vt/vn forms)
TriangleMesh readObj(const std::string& path);
// (path) => the triangles of a binary or ASCII STL file, coincident corners welded
TriangleMesh readStl(const std::string& path);

// (mesh, path) => an OBJ file; throws MeshError when it cannot be written
void writeObj(const TriangleMesh& mesh, const std::string& path);
// (mesh, path, binary or ASCII) => an STL file (facet normals from the vertex order)
void writeStl(const TriangleMesh& mesh, const std::string& path, bool binary = true);

}  // namespace yardsim::forces
