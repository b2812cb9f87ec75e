#include "forces/geometry/mesh_io.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "forces/geometry/step_reader.hpp"

namespace yardsim::forces {

using dynamics::Vector3;

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

[[noreturn]] void fail(const std::string& path, std::size_t line, const std::string& what) {
  throw MeshError(path + ":" + std::to_string(line) + ": " + what);
}

// (text stream after a keyword) => three finite numbers, or an error at this line
Vector3 readPoint(std::istringstream& in, const std::string& path, std::size_t line) {
  Vector3 p;
  if (!(in >> p.x() >> p.y() >> p.z()) || !p.allFinite())
    fail(path, line, "expected three finite coordinates");
  return p;
}

TriangleMesh readStlAscii(const std::string& path, std::ifstream& file) {
  TriangleMesh m;
  m.source = path;
  std::string text;
  std::size_t line = 0, corners = 0;
  bool solid = false;
  // (lines) => a vertex per `vertex` record; every three make a triangle at `endfacet`
  while (std::getline(file, text)) {
    ++line;
    std::istringstream in(text);
    std::string key;
    if (!(in >> key)) continue;
    key = lower(key);
    if (key == "solid") solid = true;
    else if (key == "vertex") {
      m.vertices.push_back(readPoint(in, path, line));
      ++corners;
    } else if (key == "endfacet") {
      if (corners != 3) fail(path, line, "a facet with " + std::to_string(corners) + " vertices (expected 3)");
      const int n = static_cast<int>(m.vertices.size());
      m.triangles.push_back({n - 3, n - 2, n - 1});
      corners = 0;
    } else if (key != "facet" && key != "outer" && key != "endloop" && key != "endsolid") {
      fail(path, line, "unexpected '" + key + "' in an ASCII STL file");
    }
  }
  if (!solid) fail(path, 1, "not an STL file (no 'solid' header, and not the size of a binary STL)");
  return m;
}

TriangleMesh readStlBinary(const std::string& path, std::ifstream& file, std::uint32_t count) {
  TriangleMesh m;
  m.source = path;
  m.vertices.reserve(3 * std::size_t{count});
  m.triangles.reserve(count);
  char record[50];
  for (std::uint32_t i = 0; i < count; ++i) {
    // (normal, 3 corners as little-endian float32, attribute) => three vertices
    if (!file.read(record, 50)) throw MeshError(path + ": binary STL truncated at triangle " + std::to_string(i));
    for (int k = 0; k < 3; ++k) {
      float xyz[3];
      std::memcpy(xyz, record + 12 + 12 * k, 12);
      const Vector3 v(xyz[0], xyz[1], xyz[2]);
      if (!v.allFinite())
        throw MeshError(path + ": binary STL triangle " + std::to_string(i) + " has a non-finite vertex");
      m.vertices.push_back(v);
    }
    const int n = static_cast<int>(m.vertices.size());
    m.triangles.push_back({n - 3, n - 2, n - 1});
  }
  return m;
}

}  // namespace

TriangleMesh readMesh(const std::string& path) {
  // (path) => a regular file below the size limit, before any reader opens it
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw MeshError(path + (std::filesystem::exists(path, ec) ? ": not a regular file"
                                                              : ": cannot open the mesh file"));
  if (const auto size = std::filesystem::file_size(path, ec); !ec && size > kMaxMeshFileBytes)
    throw MeshError(path + ": " + std::to_string(size) + " bytes; a mesh file has at most " +
                    std::to_string(kMaxMeshFileBytes) + " (256 MiB)");
  const std::string ext = lower(std::filesystem::path(path).extension().string());
  if (ext == ".obj") return readObj(path);
  if (ext == ".stl") return readStl(path);
  if (ext == ".step" || ext == ".stp") return readStep(path).mesh;
  throw MeshError(path + ": unknown mesh format '" + ext + "' (expected .obj, .stl, .step or .stp)");
}

TriangleMesh readClosedMesh(const std::string& path) {
  TriangleMesh m = readMesh(path);
  checkClosedMesh(m);
  return m;
}

TriangleMesh readObj(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw MeshError(path + ": cannot open the mesh file");
  TriangleMesh m;
  m.source = path;
  std::string text;
  std::size_t line = 0;
  std::vector<int> face;
  while (std::getline(file, text)) {
    ++line;
    std::istringstream in(text);
    std::string key;
    if (!(in >> key) || key[0] == '#') continue;
    if (key == "v") {
      m.vertices.push_back(readPoint(in, path, line));
    } else if (key == "f") {
      // (a, a/b, a//c, a/b/c; 1-based or negative) => 0-based indices, fanned from the first
      face.clear();
      std::string corner;
      while (in >> corner) {
        int k = 0;
        try {
          k = std::stoi(corner.substr(0, corner.find('/')));
        } catch (const std::exception&) {
          fail(path, line, "bad face corner '" + corner + "'");
        }
        const int n = static_cast<int>(m.vertices.size());
        const int index = k > 0 ? k - 1 : n + k;
        if (k == 0 || index < 0 || index >= n)
          fail(path, line, "face corner " + corner + " refers to no vertex defined before it (" +
                               std::to_string(n) + " so far)");
        face.push_back(index);
      }
      if (face.size() < 3) fail(path, line, "a face with fewer than 3 corners");
      for (std::size_t i = 1; i + 1 < face.size(); ++i) m.triangles.push_back({face[0], face[i], face[i + 1]});
    }
    // vt, vn, g, o, s, usemtl, mtllib, l, ...: not geometry of the closed surface, ignored
  }
  if (m.triangles.empty()) throw MeshError(path + ": no faces ('f' records) in the OBJ file");
  return m;
}

TriangleMesh readStl(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw MeshError(path + ": cannot open the mesh file");
  // (size == 84 + 50 n, n from the header) => binary; otherwise ASCII
  const auto size = std::filesystem::file_size(path);
  char header[84];
  std::uint32_t count = 0;
  if (size >= 84 && file.read(header, 84)) {
    std::memcpy(&count, header + 80, 4);
    if (size == 84 + 50 * std::uintmax_t{count}) {
      if (count == 0) throw MeshError(path + ": binary STL with no triangles");
      return weldVertices(readStlBinary(path, file, count));
    }
  }
  file.clear();
  file.seekg(0);
  TriangleMesh m = readStlAscii(path, file);
  if (m.triangles.empty()) throw MeshError(path + ": no facets in the ASCII STL file");
  return weldVertices(m);
}

void writeObj(const TriangleMesh& mesh, const std::string& path) {
  std::ofstream out(path);
  if (!out) throw MeshError(path + ": cannot write the mesh file");
  out << "# " << mesh.vertices.size() << " vertices, " << mesh.triangles.size() << " triangles\n"
      << std::setprecision(17);
  for (const Vector3& v : mesh.vertices) out << "v " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
  for (const auto& t : mesh.triangles) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
  if (!out) throw MeshError(path + ": writing the mesh file failed");
}

void writeStl(const TriangleMesh& mesh, const std::string& path, bool binary) {
  std::ofstream out(path, binary ? std::ios::binary : std::ios::out);
  if (!out) throw MeshError(path + ": cannot write the mesh file");
  auto normal = [&](std::size_t i) {
    const Vector3 a = areaVector(mesh, i);
    return a.norm() > 0 ? Vector3(a.normalized()) : Vector3::Zero();
  };
  auto corner = [&](std::size_t i, int k) {
    return mesh.vertices[static_cast<std::size_t>(mesh.triangles[i][static_cast<std::size_t>(k)])];
  };
  if (binary) {
    char header[80] = "yardsim binary STL";
    out.write(header, 80);
    const auto count = static_cast<std::uint32_t>(mesh.triangles.size());
    out.write(reinterpret_cast<const char*>(&count), 4);
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
      float record[12];
      const Vector3 n = normal(i);
      for (int k = 0; k < 3; ++k) record[k] = static_cast<float>(n[k]);
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k) record[3 + 3 * c + k] = static_cast<float>(corner(i, c)[k]);
      out.write(reinterpret_cast<const char*>(record), 48);
      const std::uint16_t attribute = 0;
      out.write(reinterpret_cast<const char*>(&attribute), 2);
    }
  } else {
    out << "solid yardsim\n" << std::setprecision(9);
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
      const Vector3 n = normal(i);
      out << "  facet normal " << n.x() << ' ' << n.y() << ' ' << n.z() << "\n    outer loop\n";
      for (int c = 0; c < 3; ++c)
        out << "      vertex " << corner(i, c).x() << ' ' << corner(i, c).y() << ' ' << corner(i, c).z() << '\n';
      out << "    endloop\n  endfacet\n";
    }
    out << "endsolid yardsim\n";
  }
  if (!out) throw MeshError(path + ": writing the mesh file failed");
}

}  // namespace yardsim::forces
