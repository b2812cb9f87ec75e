#include "scene/yard_reader.hpp"

#include <charconv>
#include <cstdlib>
#include <functional>

#include "forces/geometry/mesh_io.hpp"
#include "scene/mechanical_systems.hpp"
#include "scene/yaml_source.hpp"
#include "yard/block_store.hpp"
#include "yard/catalogue.hpp"

namespace yardsim::scene {
namespace fs = std::filesystem;
namespace {

// (number) => its shortest text that reads back as the same double
std::string exact(double x) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

YAML::Node scalar(double x) {
  return YAML::Node(exact(x));
}

YAML::Node list(std::initializer_list<double> xs) {
  YAML::Node n(YAML::NodeType::Sequence);
  n.SetStyle(YAML::EmitterStyle::Flow);
  for (double x : xs) n.push_back(exact(x));
  return n;
}

std::string shownList(const YAML::Node& n) {
  YAML::Emitter e;
  e.SetSeqFormat(YAML::Flow);
  e.SetMapFormat(YAML::Flow);
  e << n;
  return e.c_str();
}

// (node, file, fallback) => its mark, or the fallback when the node lost its place
SourceMark at(const YAML::Node& n, const std::string& file, const SourceMark& fallback) {
  const SourceMark m = markOf(n, file);
  return m.line > 0 ? m : fallback;
}

// (scalar node) => whether it reads as a number
bool numeric(const YAML::Node& n) {
  double x = 0;
  return n.IsScalar() && YAML::convert<double>::decode(n, x);
}

}  // namespace

void SceneYard::open(const YAML::Node& node, const fs::path& sceneFile, Diagnostics& d) {
  const std::string f = sceneFile.string();
  named_ = true;
  fs::path path;
  if (node.IsScalar() && !node.Scalar().empty()) {
    path = sceneFile.parent_path() / node.Scalar();
  } else if (node.IsMap()) {
    if (!checkKeys(node, {"env", "default"}, f, "database", d)) return;
    const YAML::Node env = node["env"], def = node["default"];
    const char* value = env && env.IsScalar() ? std::getenv(env.Scalar().c_str()) : nullptr;
    if (value && *value)
      path = value;
    else if (def && def.IsScalar())
      path = sceneFile.parent_path() / def.Scalar();
    else {
      d.error(markOf(node, f), "database",
              env && env.IsScalar() ? "the environment variable " + env.Scalar() +
                                          " is not set and there is no 'default' path"
                                    : "expected {env: VARIABLE, default: path}");
      return;
    }
  } else {
    d.error(markOf(node, f), "database",
            "expected the yard database's file (relative to this scene file) or {env: VARIABLE, "
            "default: path}");
    return;
  }
  path = path.lexically_normal();
  try {
    db_ = std::make_shared<yard::Database>(yard::Database::openReadOnly(path.string()));
    label_ =
        path.string() + " (yardsim database, schema " + std::to_string(db_->schemaVersion()) + ")";
  } catch (const yard::DatabaseError& e) {
    d.error(markOf(node, f), "database", e.what());
  }
}

bool SceneYard::need(const YAML::Node& n, const std::string& file, const std::string& keyPath,
                     const std::string& key, Diagnostics& d) const {
  if (db_) return true;
  if (named_) return false;  // the database named could not be opened: already reported
  d.error(markOf(n, file), keyPath,
          "'" + key +
              "' takes its values from the yard database: name it at the scene root "
              "(database: yard.sqlite)");
  return false;
}

std::int64_t SceneYard::rowOf(const std::string& table, const std::string& name) const {
  const auto rows = db_->query("SELECT rowid FROM " + table + " WHERE name = ?", {name});
  return rows.empty() ? 0 : static_cast<std::int64_t>(yard::asNumber(rows[0][0]));
}

std::string SceneYard::source(const std::string& table, const std::string& name,
                              std::int64_t row) const {
  return table + " row " + std::to_string(row) + " '" + name + "'";
}

std::optional<FacilityUse> SceneYard::facility(const YAML::Node& node, const std::string& file,
                                               const std::string& keyPath, Diagnostics& d) {
  if (!need(node, file, keyPath, "facility", d)) return std::nullopt;
  const std::string name = node.IsScalar() ? node.Scalar() : "";
  std::optional<yard::Facility> f = yard::findFacility(*db_, name);
  if (!f) {
    std::vector<std::string> names;
    for (const auto& x : yard::facilities(*db_)) names.push_back(x.name);
    d.error(markOf(node, file), keyPath, yard::unknownName(names, "facility", name),
            models::didYouMean(name, names));
    return std::nullopt;
  }
  FacilityUse use{(fs::path(db_->path()).parent_path() / f->modelFile).lexically_normal(), *f,
                  rowOf("facilities", name)};
  return use;
}

void SceneYard::addParticulars(const FacilityUse& use, const YAML::Node& params,
                               const std::string& instPath, const SourceMark& where,
                               const std::string& keyPath, ParamOverrides& overrides) {
  const yard::Facility& f = use.facility;
  const std::string src = source("facilities", f.name, use.row);
  provenance_.push_back({instPath, use.modelFile.string(), src + " (model file)"});
  if (!f.hookLoadCurve.empty()) {
    HookLoadCheck check{instPath, f.name, {}, {}, {}, {}, {}};
    for (const auto& p : f.hookLoadCurve) check.curve.emplace_back(p.outreach, p.capacity);
    hookLoads_.push_back(std::move(check));
  }
  const std::pair<const char*, double> particulars[] = {{"capacity", f.capacity},
                                                        {"hoist_speed", f.hoistSpeed},
                                                        {"hoist_acceleration", f.hoistAcceleration},
                                                        {"max_outreach", f.maxOutreach}};
  for (const auto& [key, value] : particulars) {
    if (!params || !params.IsMap() || !params[key]) continue;  // the model does not take it
    const std::string full = instPath + ".params." + key;
    if (overrides.count(key)) {
      provenance_.push_back({full, shownList(overrides.at(key).value),
                             "the scene (the database has " + exact(value) + ")"});
      continue;
    }
    overrides[key] = {scalar(value), where, keyPath};
    provenance_.push_back({full, exact(value), src});
  }
}

void SceneYard::expandMechanics(YAML::Node& mech, const std::string& file,
                                const std::string& keyPath, const std::string& instPath,
                                Diagnostics& d) {
  if (!mech.IsMap()) return;
  auto each = [&](const char* group, auto&& expand) {
    YAML::Node entries = mech[group];
    if (!entries.IsMap()) return;
    for (auto it = entries.begin(); it != entries.end(); ++it)
      if (it->second.IsMap())
        expand(it->second, it->first.as<std::string>(), joinKey(keyPath, std::string(group)));
  };
  each("bodies", [&](YAML::Node b, const std::string& name, const std::string& kp) {
    expandBody(b, name, file, kp, instPath, d);
  });
  for (const char* group : {"ropes", "equalizers"})
    each(group, [&](YAML::Node r, const std::string& name, const std::string& kp) {
      expandRope(r, name, file, kp, instPath, d);
    });
}

void SceneYard::expandBody(YAML::Node body, const std::string& name, const std::string& file,
                           const std::string& keyPath, const std::string& instPath,
                           Diagnostics& d) {
  const YAML::Node from = body["from_db"];
  if (!from) return;
  const std::string kp = joinKey(keyPath, name + ".from_db");
  body.remove("from_db");
  if (!need(from, file, kp, "from_db", d)) return;
  const std::string blockName = from.IsScalar() ? from.Scalar() : "";
  std::optional<yard::Block> block = yard::findBlock(*db_, blockName);
  if (!block) {
    const auto names = yard::blockNames(*db_);
    d.error(markOf(from, file), kp, yard::unknownName(names, "block", blockName),
            models::didYouMean(blockName, names));
    return;
  }
  const std::int64_t row = rowOf("blocks", blockName);
  const std::string full = instPath.empty() ? name : instPath + "." + name;
  const std::string src = source("blocks", blockName, row);
  const auto& I = block->inertia;
  // (key, value from the database, unit) => the key set unless the scene states it
  auto fill = [&](const char* key, const YAML::Node& value, const std::string& unit) {
    if (body[key]) {
      provenance_.push_back({full + "." + key, shownList(body[key]),
                             "the scene (the database has " + shownList(value) + ")"});
      return;
    }
    body[key] = value;
    provenance_.push_back({full + "." + key, shownList(value) + unit, src});
  };
  fill("mass", scalar(block->mass), " kg");
  fill("com", list({block->cog.x(), block->cog.y(), block->cog.z()}), " m");
  fill("inertia", list({I(0, 0), I(1, 1), I(2, 2), I(0, 1), I(0, 2), I(1, 2)}), " kg m^2");
  if (block->mesh || !block->meshPath.empty()) {
    YAML::Node mesh(YAML::NodeType::Map);
    mesh["database"] = db_->path();
    mesh["block"] = blockName;
    YAML::Node geometry(YAML::NodeType::Map);
    geometry["mesh"] = mesh;
    fill("geometry", geometry, "");
  }
  for (const auto& lug : block->lugs)
    provenance_.push_back({full + ".lug " + lug.name,
                           shownList(list({lug.position.x(), lug.position.y(), lug.position.z()})) +
                               " m, SWL " + exact(lug.swl) + " N",
                           src});
  bodies_[full] = {*std::move(block), row};
}

void SceneYard::expandRope(YAML::Node rope, const std::string& name, const std::string& file,
                           const std::string& keyPath, const std::string& instPath,
                           Diagnostics& d) {
  const YAML::Node from = rope["catalogue"];
  if (!from) return;
  const std::string kp = joinKey(keyPath, name + ".catalogue");
  rope.remove("catalogue");
  if (!need(from, file, kp, "catalogue", d)) return;
  const std::string ropeName = from.IsScalar() ? from.Scalar() : "";
  try {
    const yard::Rope r = yard::getRope(*db_, ropeName);
    const std::string full = instPath.empty() ? name : instPath + "." + name;
    const std::string src = source("ropes", ropeName, rowOf("ropes", ropeName));
    // (the grade's EA and MBL, N, and diameter, m: the collision capsules and clearance watches)
    struct Figure {
      const char* key;
      double value;
      const char* unit;
    };
    for (const auto& [key, value, unit] :
         {Figure{"EA", r.ea, " N"}, {"mbl", r.mbl, " N"}, {"diameter", r.diameter, " m"}}) {
      if (rope[key]) {
        provenance_.push_back({full + "." + key, shownList(rope[key]),
                               "the scene (the catalogue has " + exact(value) + ")"});
        continue;
      }
      rope[key] = scalar(value);
      provenance_.push_back({full + "." + key, exact(value) + unit, src});
    }
    provenance_.push_back({full + ".rope",
                           r.construction + ", " + exact(r.massPerMetre) +
                               " kg/m (not modelled: the rope is massless)",
                           src});
  } catch (const yard::DatabaseError& e) {
    std::vector<std::string> names;
    for (const auto& x : yard::ropes(*db_)) names.push_back(x.name);
    d.error(markOf(from, file), kp,
            "unknown rope grade '" + ropeName + "' in the catalogue of " + db_->path(),
            models::didYouMean(ropeName, names));
  }
}

void SceneYard::lugPoint(YAML::Node point, const Instance& inst, const std::string& where,
                         Diagnostics& d) {
  const std::string& instPath = inst.path;
  const std::string& file = inst.mechanicsWhere.file;
  const std::string keyPath = joinKey(joinKey(inst.keyPath, "mechanics"), where);
  const std::string element = (instPath.empty() ? "" : instPath + ".") + where;
  if (!point.IsMap()) return;
  const YAML::Node p = point["point"];
  if (!p || !p.IsScalar() || numeric(p)) return;
  const std::string body =
      point["body"] && point["body"].IsScalar() ? point["body"].Scalar() : "world";
  std::vector<std::string> known;
  for (const auto& [k, v] : bodies_) known.push_back(k);
  const std::string full = resolveName(instPath, body, known);
  if (full.empty()) {
    d.error(at(p, file, inst.mechanicsWhere), keyPath + ".point",
            "a point named '" + p.Scalar() + "' is a lug, but '" + body +
                "' is not a body from the yard database (from_db); expected [x, y, z] in m");
    return;
  }
  const DbBody& b = bodies_.at(full);
  for (const auto& lug : b.block.lugs) {
    if (lug.name != p.Scalar()) continue;
    const YAML::Node xyz = list({lug.position.x(), lug.position.y(), lug.position.z()});
    provenance_.push_back({element + ".point", shownList(xyz) + " m (lug " + lug.name + ")",
                           source("blocks", b.block.name, b.row)});
    point["point"] = xyz;
    return;
  }
  std::vector<std::string> lugs;
  for (const auto& lug : b.block.lugs) lugs.push_back(lug.name);
  d.error(at(p, file, inst.mechanicsWhere), keyPath + ".point",
          yard::unknownName(lugs, "lug", p.Scalar()) + " on block '" + b.block.name + "'",
          models::didYouMean(p.Scalar(), lugs));
}

void SceneYard::resolveLugPoints(Instance& inst, Diagnostics& d) {
  for (auto& child : inst.children) resolveLugPoints(*child, d);
  if (!inst.mechanics.IsMap() || bodies_.empty()) return;
  // (a list of points, its key path in the mechanics) => each point checked for a lug name
  auto points = [&](YAML::Node list, const std::string& kp) {
    if (!list.IsSequence()) return;
    for (std::size_t i = 0; i < list.size(); ++i)
      lugPoint(list[i], inst, kp + "[" + std::to_string(i) + "]", d);
  };
  if (YAML::Node ropes = inst.mechanics["ropes"]; ropes.IsMap())
    for (auto it = ropes.begin(); it != ropes.end(); ++it)
      if (it->second.IsMap())
        points(it->second["path"], "ropes." + it->first.as<std::string>() + ".path");
  if (YAML::Node eqs = inst.mechanics["equalizers"]; eqs.IsMap())
    for (auto it = eqs.begin(); it != eqs.end(); ++it) {
      if (!it->second.IsMap()) continue;
      const std::string kp = "equalizers." + it->first.as<std::string>();
      lugPoint(it->second["sheave"], inst, kp + ".sheave", d);
      if (YAML::Node br = it->second["branches"]; br.IsSequence())
        for (std::size_t j = 0; j < br.size(); ++j)
          points(br[j], kp + ".branches[" + std::to_string(j) + "]");
    }
}

void SceneYard::describe(Scene& scene) const {
  scene.database = label_;
  scene.provenance = provenance_;
  scene.hookLoads = hookLoads_;
}

void completeHookLoadChecks(Scene& scene, Diagnostics& d) {
  auto inside = [](const std::string& name, const std::string& crane) {
    return name.size() > crane.size() && name.compare(0, crane.size() + 1, crane + ".") == 0;
  };
  std::vector<HookLoadCheck> kept;
  for (HookLoadCheck c : scene.hookLoads) {
    for (const auto& sys : scene.systems) {
      for (const auto& r : sys->spec.ropes) {
        if (r.path.empty() || !inside(r.name, c.crane)) continue;
        if (!inside(r.path.front().first, c.crane) || inside(r.path.back().first, c.crane))
          continue;
        c.system = sys->name;
        c.ropes.emplace_back(r.name, r.parts);
        c.hoists.push_back(r.path.front().first);
      }
      for (const auto& b : sys->spec.bodies)
        if (inside(b.name, c.crane) && !inside(b.parent, c.crane)) c.root = b.name;
    }
    // (instance tree) => the crane's instance, for the warning's place
    std::function<const Instance*(const Instance&)> find =
        [&](const Instance& i) -> const Instance* {
      if (i.path == c.crane) return &i;
      for (const auto& child : i.children)
        if (const Instance* f = find(*child)) return f;
      return nullptr;
    };
    const Instance* inst = find(scene.root);
    if (c.ropes.empty() || c.root.empty()) {
      d.warning(inst ? inst->where : SourceMark{scene.file.string(), 1, 1},
                inst ? inst->keyPath : c.crane,
                "facility '" + c.facility +
                    "' has a hook-load curve but no hoist rope (a rope from "
                    "one of its bodies to a body outside it): its curve is not checked");
      continue;
    }
    kept.push_back(std::move(c));
  }
  scene.hookLoads = std::move(kept);
}

std::shared_ptr<const forces::TriangleMesh> databaseBlockMesh(const std::string& databaseFile,
                                                              const std::string& block) {
  try {
    const yard::Database db = yard::Database::openReadOnly(databaseFile);
    const yard::Block b = yard::getBlock(db, block);
    if (b.mesh) return b.mesh;
    if (b.meshPath.empty())
      throw forces::MeshError("block '" + block + "' has no mesh in " + databaseFile);
    const fs::path file = fs::path(databaseFile).parent_path() / b.meshPath;
    return std::make_shared<const forces::TriangleMesh>(
        forces::readMesh(file.lexically_normal().string()));
  } catch (const yard::DatabaseError& e) {
    throw forces::MeshError(e.what());
  }
}

}  // namespace yardsim::scene
