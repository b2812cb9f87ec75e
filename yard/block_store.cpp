#include "yard/block_store.hpp"

#include <cmath>

#include "yard/mesh_blob.hpp"
#include "yard/physical_checks.hpp"

namespace yardsim::yard {

using dynamics::Vector3;

void insertBlock(const Database& db, const Block& b) {
  const std::string what = db.path() + ": block '" + b.name + "'";
  if (b.name.empty()) throw DatabaseError(db.path() + ": a block needs a name");
  checkMass(b.mass, what);
  if (!b.cog.allFinite()) throw DatabaseError(what + ": the cog must be finite");
  checkInertia(b.inertia, what);
  for (const Lug& l : b.lugs) {
    if (!(l.swl > 0) || !std::isfinite(l.swl))
      throw DatabaseError(what + ": lug '" + l.name + "' needs a safe working load > 0 N");
    if (!(l.direction.norm() > 0) || !l.position.allFinite())
      throw DatabaseError(what + ": lug '" + l.name +
                          "' needs a finite position and a non-zero direction");
  }
  db.transaction([&] {
    if (!db.query("SELECT 1 FROM blocks WHERE name = ?", {b.name}).empty())
      throw DatabaseError(what +
                          " already exists (names are unique; pick another or remove it first)");
    Value mesh = b.mesh ? Value(meshToBlob(*b.mesh)) : Value();
    Value meshPath = b.meshPath.empty() ? Value() : Value(b.meshPath);
    const auto& I = b.inertia;
    db.execute(
        "INSERT INTO blocks (name, project, mass, cog_x, cog_y, cog_z, ixx, iyy, izz, ixy, ixz, "
        "iyz, mesh, "
        "mesh_path, weight_status, source) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
        {b.name, b.project, b.mass, b.cog.x(), b.cog.y(), b.cog.z(), I(0, 0), I(1, 1), I(2, 2),
         I(0, 1), I(0, 2), I(1, 2), mesh, meshPath, b.weightStatus, b.source});
    for (const Lug& l : b.lugs) {
      const Vector3 d = l.direction.normalized();
      db.execute(
          "INSERT INTO lugs (block, name, x, y, z, dx, dy, dz, swl) VALUES (?, ?, ?, ?, ?, ?, ?, "
          "?, ?)",
          {b.name, l.name, l.position.x(), l.position.y(), l.position.z(), d.x(), d.y(), d.z(),
           l.swl});
    }
  });
}

std::optional<Block> findBlock(const Database& db, const std::string& name) {
  const auto rows = db.query(
      "SELECT name, project, mass, cog_x, cog_y, cog_z, ixx, iyy, izz, ixy, ixz, iyz, mesh, "
      "mesh_path, "
      "weight_status, source FROM blocks WHERE name = ?",
      {name});
  if (rows.empty()) return std::nullopt;
  const Row& r = rows[0];
  Block b;
  b.name = asText(r[0]);
  b.project = asText(r[1]);
  b.mass = asNumber(r[2]);
  b.cog = Vector3(asNumber(r[3]), asNumber(r[4]), asNumber(r[5]));
  b.inertia.diagonal() << asNumber(r[6]), asNumber(r[7]), asNumber(r[8]);
  b.inertia(0, 1) = b.inertia(1, 0) = asNumber(r[9]);
  b.inertia(0, 2) = b.inertia(2, 0) = asNumber(r[10]);
  b.inertia(1, 2) = b.inertia(2, 1) = asNumber(r[11]);
  if (!isNull(r[12]))
    b.mesh = std::make_shared<const forces::TriangleMesh>(
        meshFromBlob(asBlob(r[12]), db.path() + ":" + b.name));
  b.meshPath = asText(r[13]);
  b.weightStatus = asText(r[14]);
  b.source = asText(r[15]);
  for (const Row& l : db.query(
           "SELECT name, x, y, z, dx, dy, dz, swl FROM lugs WHERE block = ? ORDER BY name", {name}))
    b.lugs.push_back({asText(l[0]), Vector3(asNumber(l[1]), asNumber(l[2]), asNumber(l[3])),
                      Vector3(asNumber(l[4]), asNumber(l[5]), asNumber(l[6])), asNumber(l[7])});
  return b;
}

Block getBlock(const Database& db, const std::string& name) {
  if (auto b = findBlock(db, name)) return *b;
  throw DatabaseError(db.path() + ": " + unknownName(blockNames(db), "block", name));
}

std::vector<std::string> blockNames(const Database& db) {
  std::vector<std::string> names;
  for (const Row& r : db.query("SELECT name FROM blocks ORDER BY name"))
    names.push_back(asText(r[0]));
  return names;
}

std::string unknownName(const std::vector<std::string>& known, const std::string& what,
                        const std::string& name) {
  std::string list;
  for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
  return "unknown " + what + " '" + name + "' (" +
         (known.empty() ? "there are none" : "the " + what + "s are " + list) + ")";
}

}  // namespace yardsim::yard
