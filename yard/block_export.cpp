#include "yard/block_export.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "forces/geometry/mesh_io.hpp"
#include "yard/database.hpp"

namespace yardsim::yard {

namespace {
// (vector) => [x, y, z] with every digit a double holds
std::string list(std::initializer_list<double> values) {
  std::ostringstream s;
  s.precision(17);
  s << '[';
  bool first = true;
  for (double v : values) {
    s << (first ? "" : ", ") << v;
    first = false;
  }
  s << ']';
  return s.str();
}
// (text) => a double-quoted YAML scalar
std::string quoted(const std::string& t) {
  std::string out = "\"";
  for (char c : t) out += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
  return out + "\"";
}
}  // namespace

std::string blockYaml(const Block& b) {
  const auto& I = b.inertia;
  std::ostringstream y;
  y.precision(17);
  y << "# block " << b.name << " exported by yardsim db export (SI units, block frame)\n"
    << "name: " << quoted(b.name) << "\nproject: " << quoted(b.project)
    << "\nweight_status: " << b.weightStatus << "\nsource: " << quoted(b.source)
    << "\nmass: " << b.mass << "  # kg\n"
    << "com: " << list({b.cog.x(), b.cog.y(), b.cog.z()}) << "  # m\n"
    << "inertia: " << list({I(0, 0), I(1, 1), I(2, 2), I(0, 1), I(0, 2), I(1, 2)})
    << "  # [Ixx, Iyy, Izz, Ixy, Ixz, Iyz] kg m^2 about com\n";
  if (b.mesh)
    y << "geometry: {mesh: " << quoted(b.name + ".obj") << "}\n";
  else if (!b.meshPath.empty())
    y << "geometry: {mesh: " << quoted(b.meshPath) << "}\n";
  if (!b.lugs.empty()) {
    y << "lugs:\n";
    for (const Lug& l : b.lugs)
      y << "  " << quoted(l.name)
        << ": {point: " << list({l.position.x(), l.position.y(), l.position.z()})
        << ", direction: " << list({l.direction.x(), l.direction.y(), l.direction.z()})
        << ", swl: " << l.swl << "}\n";
  }
  return y.str();
}

std::string exportBlock(const Block& b, const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  const std::string yaml = (std::filesystem::path(dir) / (b.name + ".yaml")).string();
  std::ofstream out(yaml);
  if (!out || !(out << blockYaml(b)))
    throw DatabaseError(yaml + ": cannot write the block's YAML file");
  if (b.mesh) {
    try {
      forces::writeObj(*b.mesh, (std::filesystem::path(dir) / (b.name + ".obj")).string());
    } catch (const forces::MeshError& e) {
      throw DatabaseError(e.what());
    }
  }
  return yaml;
}

}  // namespace yardsim::yard
