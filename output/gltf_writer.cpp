#include "output/gltf_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>

#include "devs/trace_format.hpp"

namespace yardsim::output {

using mechanics::MechanicsSpec;
using models::Replay;
using models::ReplayBody;
namespace {

using devs::appendJsonNumber;
using devs::appendJsonString;
using Shape = MechanicsSpec::Visual::Shape;

struct Mesh {
  std::vector<float> position, normal;  // x, y, z per vertex
  std::vector<std::uint32_t> index;     // triangles, counter-clockwise seen from outside
  void vertex(const dynamics::Vector3& p, const dynamics::Vector3& n) {
    for (int k = 0; k < 3; ++k) {
      position.push_back(static_cast<float>(p[k]));
      normal.push_back(static_cast<float>(n[k]));
    }
  }
  std::uint32_t size() const { return static_cast<std::uint32_t>(position.size() / 3); }
  void quad(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    index.insert(index.end(), {a, b, c, a, c, d});
  }
};

// (half extents) => a box centred on the origin, four vertices per face (flat normals)
void box(Mesh& m, const dynamics::Vector3& h) {
  for (int axis = 0; axis < 3; ++axis)
    for (double s : {1.0, -1.0}) {
      dynamics::Vector3 n = dynamics::Vector3::Zero();
      n[axis] = s;
      const dynamics::Vector3 u = dynamics::Vector3::Unit((axis + 1) % 3) * s;
      const dynamics::Vector3 v = n.cross(u);
      const std::uint32_t o = m.size();
      for (auto [a, b] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}})
        m.vertex((n + a * u + b * v).cwiseProduct(h), n);
      m.quad(o, o + 1, o + 2, o + 3);
    }
}

// (radius, length) => a cylinder along z centred on the origin, with caps
void cylinder(Mesh& m, double r, double length, int segments = 32) {
  const double h = 0.5 * length;
  const std::uint32_t side = m.size();
  for (int i = 0; i <= segments; ++i) {
    const double a = 2.0 * M_PI * i / segments;
    const dynamics::Vector3 n(std::cos(a), std::sin(a), 0.0);
    m.vertex(r * n + dynamics::Vector3(0, 0, -h), n);
    m.vertex(r * n + dynamics::Vector3(0, 0, h), n);
  }
  for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(segments); ++i) {
    const std::uint32_t a = side + 2 * i;
    m.quad(a, a + 2, a + 3, a + 1);
  }
  for (double s : {1.0, -1.0}) {
    const dynamics::Vector3 n(0, 0, s);
    const std::uint32_t c = m.size();
    m.vertex(n * h, n);
    for (int i = 0; i <= segments; ++i) {
      const double a = 2.0 * M_PI * i / segments;
      m.vertex(dynamics::Vector3(r * std::cos(a), r * std::sin(a), s * h), n);
    }
    for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(segments); ++i)
      if (s > 0) m.index.insert(m.index.end(), {c, c + 1 + i, c + 2 + i});
      else m.index.insert(m.index.end(), {c, c + 2 + i, c + 1 + i});
  }
}

// (radius) => a latitude-longitude sphere centred on the origin
void sphere(Mesh& m, double r, int rings = 12, int segments = 24) {
  const std::uint32_t o = m.size();
  for (int i = 0; i <= rings; ++i) {
    const double th = M_PI * i / rings;
    for (int j = 0; j <= segments; ++j) {
      const double ph = 2.0 * M_PI * j / segments;
      const dynamics::Vector3 n(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
      m.vertex(r * n, n);
    }
  }
  const auto w = static_cast<std::uint32_t>(segments + 1);
  for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(rings); ++i)
    for (std::uint32_t j = 0; j < static_cast<std::uint32_t>(segments); ++j) {
      const std::uint32_t a = o + i * w + j;
      m.quad(a, a + w, a + w + 1, a + 1);
    }
}

// (triangle mesh) => its triangles with flat normals (three vertices each)
void triangles(Mesh& m, const forces::TriangleMesh& t) {
  for (const auto& f : t.triangles) {
    const dynamics::Vector3 &a = t.vertices[f[0]], &b = t.vertices[f[1]], &c = t.vertices[f[2]];
    dynamics::Vector3 n = (b - a).cross(c - a);
    n = n.norm() > 0 ? n.normalized() : dynamics::Vector3::UnitZ();
    const std::uint32_t o = m.size();
    for (const auto* v : {&a, &b, &c}) m.vertex(*v, n);
    m.index.insert(m.index.end(), {o, o + 1, o + 2});
  }
}

// (body) => its shape's mesh in the body frame
Mesh shapeMesh(const ReplayBody& b) {
  Mesh m;
  if (b.shape == Shape::Mesh && b.mesh) triangles(m, *b.mesh);
  else switch (b.shape) {
    case Shape::Cylinder: cylinder(m, b.size[0], b.size[1]); break;
    case Shape::Sphere: sphere(m, b.size[0]); break;
    default: box(m, 0.5 * b.size); break;
  }
  for (std::size_t v = 0; v < m.size(); ++v) {
    float* p = &m.position[3 * v];
    float* n = &m.normal[3 * v];
    const dynamics::Vector3 pB = b.X_BG.actPoint(dynamics::Vector3(p[0], p[1], p[2]));
    const dynamics::Vector3 nB = b.X_BG.R * dynamics::Vector3(n[0], n[1], n[2]);
    for (int k = 0; k < 3; ++k) {
      p[k] = static_cast<float>(pB[k]);
      n[k] = static_cast<float>(nB[k]);
    }
  }
  return m;
}

// The binary buffer and the accessors into it, as JSON text.
struct Builder {
  std::vector<std::uint8_t> bin;
  std::string views, accessors;
  int nViews = 0, nAccessors = 0;

  // (bytes, target or 0) => a buffer view, 4-byte aligned
  int view(const void* data, std::size_t bytes, int target) {
    const std::size_t offset = bin.size();
    bin.resize(offset + bytes);
    if (bytes) std::memcpy(bin.data() + offset, data, bytes);  // (never with a null source)
    bin.resize((bin.size() + 3) / 4 * 4, 0);
    if (nViews) views += ',';
    views += "{\"buffer\":0,\"byteOffset\":" + std::to_string(offset) +
             ",\"byteLength\":" + std::to_string(bytes);
    if (target) views += ",\"target\":" + std::to_string(target);
    views += '}';
    return nViews++;
  }
  // (values, components per element, type, target) => an accessor with min and max
  template <class T>
  int accessor(const std::vector<T>& values, int components, const char* type, int target) {
    const int v = view(values.data(), values.size() * sizeof(T), target);
    std::vector<double> lo(static_cast<std::size_t>(components), std::numeric_limits<double>::infinity());
    std::vector<double> hi(lo.size(), -std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < values.size(); ++i) {
      const auto k = i % lo.size();
      lo[k] = std::min(lo[k], static_cast<double>(values[i]));
      hi[k] = std::max(hi[k], static_cast<double>(values[i]));
    }
    auto list = [](const std::vector<double>& xs) {
      std::string s = "[";
      for (std::size_t i = 0; i < xs.size(); ++i) {
        if (i) s += ',';
        appendJsonNumber(s, xs[i]);
      }
      return s + "]";
    };
    constexpr bool isFloat = std::is_same_v<T, float>;
    if (nAccessors) accessors += ',';
    accessors += "{\"bufferView\":" + std::to_string(v) +
                 ",\"componentType\":" + std::to_string(isFloat ? 5126 : 5125) +
                 ",\"count\":" + std::to_string(values.size() / lo.size()) + ",\"type\":\"" + type +
                 "\",\"min\":" + list(lo) + ",\"max\":" + list(hi) + "}";
    return nAccessors++;
  }
};

template <std::size_t N>
std::vector<float> flat(const std::vector<std::array<float, N>>& xs) {
  std::vector<float> out;
  out.reserve(xs.size() * N);
  for (const auto& x : xs) out.insert(out.end(), x.begin(), x.end());
  return out;
}

void appendU32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) out.push_back(static_cast<std::uint8_t>(v >> (8 * k)));
}

}  // namespace

std::vector<std::uint8_t> glbBytes(const Replay& replay) {
  const std::size_t frames = replay.times.size();
  for (const auto& b : replay.bodies)
    if (b.translation.size() != frames || b.rotation.size() != (b.marker ? 0 : frames))
      throw std::invalid_argument("replay: body '" + b.name + "' has " +
                                  std::to_string(b.translation.size()) + " poses for " +
                                  std::to_string(frames) + " frames");
  Builder g;
  std::string nodes, meshes, samplers, channels;
  int nSamplers = 0;
  // (root) => z-up world to y-up: -90 deg about x
  nodes = "{\"name\":\"world\",\"rotation\":[";
  appendJsonNumber(nodes, -std::sqrt(0.5));
  nodes += ",0,0,";
  appendJsonNumber(nodes, std::sqrt(0.5));
  nodes += "],\"children\":[";
  for (std::size_t i = 0; i < replay.bodies.size(); ++i)
    nodes += (i ? "," : "") + std::to_string(i + 1);
  nodes += "]}";
  const int time = frames ? g.accessor(replay.times, 1, "SCALAR", 0) : -1;
  static const char* const kPalette[] = {"0.85,0.55,0.13", "0.20,0.47,0.75", "0.40,0.65,0.30",
                                         "0.75,0.30,0.30", "0.55,0.40,0.70", "0.35,0.65,0.70"};
  std::string materials;
  std::size_t nMeshes = 0;
  for (std::size_t i = 0; i < replay.bodies.size(); ++i) {
    const ReplayBody& b = replay.bodies[i];
    // (shape) => its mesh and material (none for a marker)
    const std::string mesh = std::to_string(nMeshes);
    if (!b.marker) {
      const Mesh m = shapeMesh(b);
      const int pos = g.accessor(m.position, 3, "VEC3", 34962);
      const int nrm = g.accessor(m.normal, 3, "VEC3", 34962);
      const int idx = g.accessor(m.index, 1, "SCALAR", 34963);
      const std::string c = kPalette[i % (sizeof kPalette / sizeof *kPalette)];
      materials += std::string(nMeshes ? "," : "") +
                   "{\"pbrMetallicRoughness\":{\"baseColorFactor\":[" + c +
                   ",1],\"metallicFactor\":0.1,\"roughnessFactor\":0.7}}";
      meshes += std::string(nMeshes ? "," : "") + "{\"name\":";
      appendJsonString(meshes, b.name);
      meshes += ",\"primitives\":[{\"attributes\":{\"POSITION\":" + std::to_string(pos) +
                ",\"NORMAL\":" + std::to_string(nrm) + "},\"indices\":" + std::to_string(idx) +
                ",\"material\":" + mesh + "}]}";
      ++nMeshes;
    }
    // (first pose) => node i + 1, its rest pose
    nodes += ",{\"name\":";
    appendJsonString(nodes, b.name);
    if (!b.marker) nodes += ",\"mesh\":" + mesh;
    if (frames) {
      std::string t, r;
      for (int k = 0; k < 3; ++k) appendJsonNumber(t += k ? "," : "", b.translation[0][static_cast<std::size_t>(k)]);
      nodes += ",\"translation\":[" + t + "]";
      if (!b.marker) {
        for (int k = 0; k < 4; ++k)
          appendJsonNumber(r += k ? "," : "", b.rotation[0][static_cast<std::size_t>(k)]);
        nodes += ",\"rotation\":[" + r + "]";
      }
    }
    nodes += ",\"extras\":{\"body\":";
    appendJsonString(nodes, b.name);
    nodes += "}}";
    if (!frames) continue;
    // (poses) => samplers and channels of node i + 1 (a marker's translation only)
    const int tr = g.accessor(flat(b.translation), 3, "VEC3", 0);
    const int ro = b.marker ? -1 : g.accessor(flat(b.rotation), 4, "VEC4", 0);
    for (auto [out, path] : {std::pair{tr, "translation"}, {ro, "rotation"}}) {
      if (out < 0) continue;
      const int k = nSamplers++;
      samplers += std::string(k ? "," : "") + "{\"input\":" + std::to_string(time) +
                  ",\"output\":" + std::to_string(out) + ",\"interpolation\":\"LINEAR\"}";
      channels += std::string(k ? "," : "") + "{\"sampler\":" + std::to_string(k) +
                  ",\"target\":{\"node\":" + std::to_string(i + 1) + ",\"path\":\"" + path + "\"}}";
    }
  }
  // (ropes) => the scene's extras
  std::string ropes;
  for (std::size_t r = 0; r < replay.ropes.size(); ++r) {
    ropes += r ? ",{\"name\":" : "{\"name\":";
    appendJsonString(ropes, replay.ropes[r].name);
    ropes += ",\"points\":[";
    for (std::size_t k = 0; k < replay.ropes[r].points.size(); ++k) {
      const auto& [node, p] = replay.ropes[r].points[k];
      ropes += (k ? ",{\"node\":" : "{\"node\":") + std::to_string(node) + ",\"p\":[";
      for (int j = 0; j < 3; ++j) appendJsonNumber(ropes += j ? "," : "", p[j]);
      ropes += "]}";
    }
    ropes += "]}";
  }
  std::string json = "{\"asset\":{\"version\":\"2.0\",\"generator\":\"yardsim\"},\"scene\":0,"
                     "\"scenes\":[{\"name\":\"replay\",\"nodes\":[0],\"extras\":{\"yardsim_ropes\":[" +
                     ropes + "]}}],\"nodes\":[" + nodes + "]";
  if (!meshes.empty()) json += ",\"meshes\":[" + meshes + "],\"materials\":[" + materials + "]";
  if (!channels.empty())
    json += ",\"animations\":[{\"name\":\"replay\",\"samplers\":[" + samplers + "],\"channels\":[" +
            channels + "]}]";
  if (!g.bin.empty())
    json += ",\"buffers\":[{\"byteLength\":" + std::to_string(g.bin.size()) + "}],\"bufferViews\":[" +
            g.views + "],\"accessors\":[" + g.accessors + "]";
  json += "}";
  json.resize((json.size() + 3) / 4 * 4, ' ');
  // (JSON, BIN) => header and chunks
  std::vector<std::uint8_t> out;
  const std::size_t total = 12 + 8 + json.size() + (g.bin.empty() ? 0 : 8 + g.bin.size());
  appendU32(out, 0x46546C67u);  // "glTF"
  appendU32(out, 2);
  appendU32(out, static_cast<std::uint32_t>(total));
  appendU32(out, static_cast<std::uint32_t>(json.size()));
  appendU32(out, 0x4E4F534Au);  // "JSON"
  out.insert(out.end(), json.begin(), json.end());
  if (!g.bin.empty()) {
    appendU32(out, static_cast<std::uint32_t>(g.bin.size()));
    appendU32(out, 0x004E4942u);  // "BIN\0"
    out.insert(out.end(), g.bin.begin(), g.bin.end());
  }
  return out;
}

void writeGlb(const Replay& replay, const std::filesystem::path& file) {
  const auto bytes = glbBytes(replay);
  std::ofstream out(file, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error("cannot write '" + file.string() + "'");
}

}  // namespace yardsim::output
