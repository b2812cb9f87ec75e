#include "yard/mesh_blob.hpp"

#include <cstdint>
#include <cstring>

#include "yard/database.hpp"

namespace yardsim::yard {

namespace {
// (bytes, value) => the value's bytes appended (the machines we build for are little-endian)
template <class T>
void put(std::vector<unsigned char>& out, T value) {
  unsigned char b[sizeof(T)];
  std::memcpy(b, &value, sizeof(T));
  out.insert(out.end(), b, b + sizeof(T));
}
}  // namespace

std::vector<unsigned char> meshToBlob(const forces::TriangleMesh& mesh) {
  std::vector<unsigned char> out{'Y', 'S', 'M', '1'};
  out.reserve(12 + 24 * mesh.vertices.size() + 12 * mesh.triangles.size());
  put(out, static_cast<std::uint32_t>(mesh.vertices.size()));
  put(out, static_cast<std::uint32_t>(mesh.triangles.size()));
  for (const auto& v : mesh.vertices)
    for (int k = 0; k < 3; ++k) put(out, v[k]);
  for (const auto& t : mesh.triangles)
    for (int k : t) put(out, static_cast<std::int32_t>(k));
  return out;
}

forces::TriangleMesh meshFromBlob(const std::vector<unsigned char>& blob,
                                  const std::string& source) {
  std::uint32_t nv = 0, nt = 0;
  if (blob.size() < 12 || std::memcmp(blob.data(), "YSM1", 4) != 0)
    throw DatabaseError(source + ": the stored mesh is not a yardsim mesh blob");
  std::memcpy(&nv, blob.data() + 4, 4);
  std::memcpy(&nt, blob.data() + 8, 4);
  if (blob.size() != 12 + 24 * std::size_t{nv} + 12 * std::size_t{nt})
    throw DatabaseError(source + ": the stored mesh is truncated");
  forces::TriangleMesh m;
  m.source = source;
  m.vertices.resize(nv);
  m.triangles.resize(nt);
  const unsigned char* p = blob.data() + 12;
  for (auto& v : m.vertices)
    for (int k = 0; k < 3; ++k, p += 8) std::memcpy(&v[k], p, 8);
  for (auto& t : m.triangles)
    for (int& k : t) {
      std::int32_t i = 0;
      std::memcpy(&i, p, 4);
      p += 4;
      if (i < 0 || static_cast<std::uint32_t>(i) >= nv)
        throw DatabaseError(source + ": the stored mesh has a bad index");
      k = i;
    }
  return m;
}

}  // namespace yardsim::yard
