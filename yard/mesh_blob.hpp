#pragma once
// A triangle mesh as a database blob, exactly: "YSM1", vertex count and triangle count (uint32,
// little-endian), the vertices as float64 x, y, z (m), the triangles as int32 corner indices.
#include <vector>

#include "forces/geometry/triangle_mesh.hpp"

namespace yardsim::yard {

// (mesh) => its blob
std::vector<unsigned char> meshToBlob(const forces::TriangleMesh& mesh);
// (blob, source for errors) => the mesh; DatabaseError when the blob is not one of ours
forces::TriangleMesh meshFromBlob(const std::vector<unsigned char>& blob,
                                  const std::string& source);

}  // namespace yardsim::yard
