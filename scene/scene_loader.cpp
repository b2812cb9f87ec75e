#include "scene/scene_loader.hpp"

#include <chrono>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>

#include "models/port_types.hpp"
#include "scene/coupling_graph.hpp"
#include "scene/event_checks.hpp"
#include "scene/integrator_reader.hpp"
#include "scene/loop_gap_check.hpp"
#include "scene/mechanical_systems.hpp"
#include "scene/provider_readers.hpp"
#include "scene/resource_limits.hpp"
#include "scene/run_settings_reader.hpp"
#include "scene/sha256.hpp"
#include "scene/stiffness_guard.hpp"
#include "scene/yaml_source.hpp"
#include "scene/yard_reader.hpp"

namespace yardsim::scene {

using models::Diagnostics;
using models::ParamCheck;
using models::ParamKind;
using models::ParamSpec;
using models::PortSpec;
using models::Registry;
using models::SceneError;
using models::SourceMark;
using models::TypeInfo;
using models::describe;
using models::didYouMean;
using models::findPortType;
using models::hasKind;
using models::portTypeNames;
namespace fs = std::filesystem;

namespace {

const std::vector<std::string> kFileKeys{"schema_version", "name",      "description",
                                         "params",         "inputs",    "outputs",
                                         "components",     "couplings", "mechanics"};
const std::vector<std::string> kRootKeys{"record",     "report",    "until",    "seed",
                                         "integrator", "trace",     "wp",       "limits",
                                         "database",   "collision", "clearance"};
const std::vector<std::string> kInlineKeys{"description", "params",    "inputs",   "outputs",
                                           "components",  "couplings", "mechanics"};
const std::vector<std::string> kComponentKeys{"type",   "include",   "coupled",    "facility",
                                              "params", "placement", "description"};

using Override = ParamOverride;
using Overrides = ParamOverrides;

bool validName(const std::string& n) {
  return !n.empty() && n.find_first_of(". \t\"") == std::string::npos;
}

class Loader {
 public:
  explicit Loader(Diagnostics& d) : d_(d) {}

  std::unique_ptr<Scene> root(const fs::path& file, const Overrides& overrides) {
    auto scene = std::make_unique<Scene>();
    scene->file = file;
    std::string text;
    const auto parsed = parse(file, {}, "", &text);
    if (!parsed) return nullptr;
    const YAML::Node& doc = *parsed;
    scene->sha256 = sha256Hex(text);
    scene->root.name = file.stem().string();
    scene->root.where = {file.string(), 1, 1};
    std::error_code ec;
    const fs::path canon = fs::weakly_canonical(file, ec);
    stack_.push_back(ec ? file : canon);
    if (doc.IsMap() && doc["database"]) yard_.open(doc["database"], file, d_);
    Scope scope;
    fileBody(scene->root, doc, file, scope, overrides, true);
    if (doc.IsMap()) sceneCollision(scene->root, doc, file.string(), scope);
    readRunSettings(*scene, doc, file.string(), d_);
    yard_.resolveLugPoints(scene->root, d_);
    yard_.describe(*scene);
    stack_.pop_back();
    return scene;
  }

 private:
  // (file) => parsed document, or nullopt with a diagnostic
  std::optional<YAML::Node> parse(const fs::path& file, const SourceMark& from,
                                  const std::string& keyPath, std::string* text = nullptr) {
    return readYamlFile(file, from, keyPath, d_, text);
  }

  // (the root's `collision:` and `clearance:`) => one collision set named `collision` in the
  // root's mechanics, which every body with a geometry joins unless `bodies:` lists them
  // (scene/providers/collision_reader.cpp, docs/collision.md)
  void sceneCollision(Instance& root, const YAML::Node& doc, const std::string& f, Scope& scope) {
    const YAML::Node col = doc["collision"], watch = doc["clearance"];
    if (!col && !watch) return;
    if (col && !col.IsMap()) {
      d_.error(markOf(col, f), "collision",
               "expected a mapping {ground, materials, contact, ignore, shapes, bodies, ...}");
      return;
    }
    if (watch && !watch.IsMap()) {
      d_.error(markOf(watch, f), "clearance", "expected {name: {between: [a, b], below: m}, ...}");
      return;
    }
    YAML::Node entry =
        col ? resolveRefs(col, scope, f, "collision", d_) : YAML::Node(YAML::NodeType::Map);
    if (watch) entry["clearance"] = resolveRefs(watch, scope, f, "clearance", d_);
    entry["_scene"] = col ? "contact" : "watch";
    if (!root.mechanics.IsDefined() || !root.mechanics.IsMap()) {
      root.mechanics = YAML::Node(YAML::NodeType::Map);
      root.mechanicsWhere = markOf(col ? col : watch, f);
    }
    const YAML::Node sets = root.mechanics["collision"];
    if (sets && sets.IsMap() && sets["collision"]) {
      d_.error(markOf(sets["collision"], f), "mechanics.collision.collision",
               "the set name 'collision' is the scene-level collision's: rename this set");
      return;
    }
    root.mechanics["collision"]["collision"] = entry;
  }

  // (a file's top-level mapping) => a coupled instance; overrides replace its params' defaults
  void fileBody(Instance& inst, const YAML::Node& doc, const fs::path& file, Scope& scope,
                const Overrides& overrides,
                bool isRoot) {
    const std::string f = file.string();
    std::vector<std::string> keys = kFileKeys;
    if (isRoot) keys.insert(keys.end(), kRootKeys.begin(), kRootKeys.end());
    checkKeys(doc, keys, f, "", d_);
    const YAML::Node version = doc["schema_version"];
    if (!version) {
      d_.error({f, 1, 1}, "schema_version", "missing required key 'schema_version' (expected 1)");
    } else if (!version.IsScalar() || version.Scalar() != "1") {
      d_.error(markOf(version, f), "schema_version",
               "unsupported schema_version " + shown(version) + "; expected 1");
    }
    coupledBody(inst, doc, f, fs::path(file).parent_path(), scope, overrides, "");
  }

  void coupledBody(Instance& inst, const YAML::Node& def, const std::string& f,
                   const fs::path& dir, Scope& scope,
                   const Overrides& overrides,
                   const std::string& kp) {
    // (params block, overrides) => this model's scope
    const YAML::Node params = def["params"];
    std::set<std::string> declared;
    if (params && !params.IsMap()) {
      d_.error(markOf(params, f), joinKey(kp, "params"), "expected a mapping of named values");
    } else if (params) {
      for (auto it = params.begin(); it != params.end(); ++it) {
        const auto key = it->first.as<std::string>();
        declared.insert(key);
        auto o = overrides.find(key);
        scope.values[key] = o != overrides.end()
                                ? o->second.value
                                : resolveRefs(it->second, scope, f, joinKey(kp, "params." + key), d_);
      }
    }
    for (const auto& [key, value] : overrides) {
      if (declared.count(key)) continue;
      d_.error(value.where, value.keyPath,
               "no parameter '" + key + "' to override in '" + inst.path +
                   "'; it declares: " + list(declared),
               didYouMean(key, {declared.begin(), declared.end()}));
    }
    ports(inst, def["inputs"], true, f, joinKey(kp, "inputs"));
    ports(inst, def["outputs"], false, f, joinKey(kp, "outputs"));
    const YAML::Node comps = def["components"];
    if (comps && !comps.IsMap()) {
      d_.error(markOf(comps, f), joinKey(kp, "components"),
               "expected a mapping from component names to their definitions");
    } else if (comps) {
      std::set<std::string> names;
      for (auto it = comps.begin(); it != comps.end(); ++it) {
        const auto name = it->first.as<std::string>();
        const std::string ckp = joinKey(kp, "components." + name);
        if (!names.insert(name).second) {
          d_.error(markOf(it->first, f), ckp, "duplicate component name '" + name + "'");
          continue;
        }
        if (!validName(name)) {
          d_.error(markOf(it->first, f), ckp,
                   "component name '" + name + "' may not contain dots, quotes or spaces");
          continue;
        }
        auto child = std::make_unique<Instance>();
        child->name = name;
        child->path = inst.path.empty() ? name : inst.path + "." + name;
        child->where = markOf(it->first, f);
        child->keyPath = ckp;
        if (component(*child, it->second, f, dir, scope, ckp)) inst.children.push_back(std::move(child));
      }
    }
    couplings(inst, def["couplings"], f, joinKey(kp, "couplings"));
    if (const YAML::Node mech = def["mechanics"]) {
      if (!mech.IsMap()) {
        d_.error(markOf(mech, f), joinKey(kp, "mechanics"),
                 "expected a mapping with bodies, ropes, equalizers, loops, gravity, water, wind, "
                 "hydrostatics, wind_loads, current_loads, damping");
      } else {
        inst.mechanics = resolveRefs(mech, scope, f, joinKey(kp, "mechanics"), d_);
        yard_.expandMechanics(inst.mechanics, f, joinKey(kp, "mechanics"), inst.path, d_);
        inst.mechanicsWhere = markOf(mech, f);
        checkKeys(mech, mechanicsKeys(), f, joinKey(kp, "mechanics"), d_);
      }
    }
  }

  // (component definition) => an atomic or coupled child; false when it cannot be built at all
  bool component(Instance& c, const YAML::Node& def, const std::string& f, const fs::path& dir,
                 const Scope& scope, const std::string& kp) {
    if (!def.IsMap()) {
      d_.error(markOf(def, f), kp, "expected a mapping with 'type', 'include' or 'coupled'");
      return false;
    }
    checkKeys(def, kComponentKeys, f, kp, d_);
    const int kinds = int(bool(def["type"])) + int(bool(def["include"])) +
                      int(bool(def["coupled"])) + int(bool(def["facility"]));
    if (kinds != 1) {
      d_.error(markOf(def, f), kp,
               kinds == 0 ? "missing required key: one of 'type' (an atomic model type), "
                            "'include' (a file), 'coupled' (an inline coupled model) or "
                            "'facility' (a crane of the yard database)"
                          : "give only one of 'type', 'include', 'coupled' and 'facility'");
      return false;
    }
    if (const YAML::Node p = def["placement"]) placement(c, p, f, joinKey(kp, "placement"));
    const YAML::Node params = def["params"];
    if (params && !params.IsMap()) {
      d_.error(markOf(params, f), joinKey(kp, "params"), "expected a mapping of parameters");
      return false;
    }
    if (const YAML::Node t = def["type"]) return atomic(c, t, params, f, scope, kp);

    // (params given at the instance) => overrides, resolved where the instance is written
    Overrides overrides;
    if (params)
      for (auto it = params.begin(); it != params.end(); ++it) {
        const auto key = it->first.as<std::string>();
        const std::string okp = joinKey(kp, "params." + key);
        overrides[key] = {resolveRefs(it->second, scope, f, okp, d_), markOf(it->first, f), okp};
      }
    if (const YAML::Node inl = def["coupled"]) {
      if (!inl.IsMap()) {
        d_.error(markOf(inl, f), joinKey(kp, "coupled"), "expected a coupled model definition");
        return false;
      }
      checkKeys(inl, kInlineKeys, f, joinKey(kp, "coupled"), d_);
      Scope inner;
      inner.parent = &scope;
      coupledBody(c, inl, f, dir, inner, overrides, joinKey(kp, "coupled"));
      return true;
    }
    // (include: file, or facility: name) => the file, a facility's particulars as parameters
    std::optional<FacilityUse> facility;
    if (def["facility"] &&
        !(facility = yard_.facility(def["facility"], f, joinKey(kp, "facility"), d_)))
      return false;
    const YAML::Node inc = facility ? def["facility"] : def["include"];
    if (!facility && !inc.IsScalar()) {
      d_.error(markOf(inc, f), joinKey(kp, "include"), "expected a file path");
      return false;
    }
    const fs::path file = facility ? facility->modelFile : dir / inc.Scalar();
    std::error_code
        ec;  // (a name too long for the file system, ...) => refused where it is written
    const fs::path canon = fs::weakly_canonical(file, ec);
    if (ec) {
      d_.error(markOf(inc, f), joinKey(kp, "include"),
               "cannot read '" + inc.Scalar() + "': " + ec.message());
      return false;
    }
    for (std::size_t i = 0; i < stack_.size(); ++i) {
      if (stack_[i] != canon) continue;
      std::string chain;
      for (std::size_t j = i; j < stack_.size(); ++j) chain += stack_[j].filename().string() + " -> ";
      d_.error(markOf(inc, f), joinKey(kp, "include"),
               "include cycle: " + chain + canon.filename().string());
      return false;
    }
    const auto doc = parse(file, markOf(inc, f), joinKey(kp, "include"));
    if (!doc) return false;
    if (facility)
      yard_.addParticulars(*facility, (*doc)["params"], c.path, markOf(inc, f),
                           joinKey(kp, "facility"), overrides);
    c.source = file.string();
    stack_.push_back(canon);
    Scope own;  // an included file sees only its own params
    fileBody(c, *doc, file, own, overrides, false);
    stack_.pop_back();
    return true;
  }

  bool atomic(Instance& c, const YAML::Node& typeNode, const YAML::Node& params,
              const std::string& f, const Scope& scope, const std::string& kp) {
    const std::string typeName = typeNode.IsScalar() ? typeNode.Scalar() : "";
    const TypeInfo* type = Registry::instance().find(typeName);
    if (!type) {
      d_.error(markOf(typeNode, f), joinKey(kp, "type"),
               "unknown model type " + shown(typeNode) + " (see `yardsim list-types`)",
               didYouMean(typeName, Registry::instance().names()));
      return false;
    }
    c.type = type;
    std::vector<std::string> known;
    for (const auto& p : type->params) known.push_back(p.name);
    const std::string pkp = joinKey(kp, "params");
    bool ok = true;
    if (params) ok = checkKeys(params, known, f, pkp, d_);
    // a misspelt key already says which parameter it meant: don't also call that one missing
    std::set<std::string> meant;
    if (params)
      for (auto it = params.begin(); it != params.end(); ++it) {
        const auto key = it->first.as<std::string>();
        if (std::find(known.begin(), known.end(), key) == known.end())
          if (const std::string h = didYouMean(key, known); !h.empty())
            meant.insert(h.substr(14, h.size() - 16));  // "did you mean 'x'?" => x
      }
    for (const auto& spec : type->params) {
      const YAML::Node given = params ? params[spec.name] : params;  // undefined when absent
      if (given) {
        const std::size_t before = d_.errorCount();
        const YAML::Node value = resolveRefs(given, scope, f, joinKey(pkp, spec.name), d_);
        if (d_.errorCount() > before) {
          ok = false;  // an unknown $name, already reported
        } else if (!hasKind(value, spec.kind)) {
          d_.error(markOf(given, f), joinKey(pkp, spec.name),
                   "expected " + describe(spec.kind) + unitNote(spec) + ", got " + shown(value));
          ok = false;
        }
        c.params.set(spec.name, value, markOf(given, f));
      } else if (spec.required && meant.count(spec.name)) {
        ok = false;
      } else if (spec.required) {
        d_.error(params ? markOf(params, f) : c.where, pkp,
                 "missing required parameter '" + spec.name + "' (" + describe(spec.kind) +
                     unitNote(spec) + ") of type '" + type->name + "'");
        ok = false;
      } else {
        c.params.set(spec.name, YAML::Load(spec.defaultValue), c.where);
      }
    }
    if (!ok) return true;  // keep the instance so couplings to it are still checked
    const std::size_t before = d_.errorCount();
    if (type->check) {
      ParamCheck check(d_, c.params, pkp);
      type->check(c.params, check);
    }
    if (d_.errorCount() == before) {
      c.ports = type->ports(c.params);
      c.feedthrough = type->feedthrough && type->feedthrough(c.params);
    }
    return true;
  }

  static std::string unitNote(const ParamSpec& s) { return s.unit.empty() ? "" : " in " + s.unit; }

  static std::string list(const std::set<std::string>& names) {
    std::string out;
    for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
    return out.empty() ? "nothing" : out;
  }

  void ports(Instance& inst, const YAML::Node& node, bool input, const std::string& f,
             const std::string& kp) {
    if (!node) return;
    if (!node.IsMap()) {
      d_.error(markOf(node, f), kp, "expected a mapping from port names to value types");
      return;
    }
    for (auto it = node.begin(); it != node.end(); ++it) {
      const auto name = it->first.as<std::string>();
      const std::string type = it->second.IsScalar() ? it->second.Scalar() : "";
      if (!validName(name)) {
        d_.error(markOf(it->first, f), joinKey(kp, name),
                 "port name '" + name + "' may not contain dots, quotes or spaces");
      } else if (inst.port(name)) {
        d_.error(markOf(it->first, f), joinKey(kp, name), "duplicate port name '" + name + "'");
      } else if (!findPortType(type)) {
        d_.error(markOf(it->second, f), joinKey(kp, name),
                 "unknown port value type " + shown(it->second) + "; expected one of: int, "
                 "double, bool, string, setpoint, mechanics_event",
                 didYouMean(type, portTypeNames()));
      } else {
        inst.ports.push_back({name, type, input});
      }
    }
  }

  void placement(Instance& c, const YAML::Node& node, const std::string& f, const std::string& kp) {
    if (!node.IsMap()) {
      d_.error(markOf(node, f), kp, "expected a mapping with 'xyz' (m) and 'rpy_deg' (degrees)");
      return;
    }
    checkKeys(node, {"xyz", "rpy_deg"}, f, kp, d_);
    auto triple = [&](const char* key, std::array<double, 3>& out) {
      const YAML::Node v = node[key];
      if (!v) return;
      if (!hasKind(v, ParamKind::NumberList) || v.size() != 3) {
        d_.error(markOf(v, f), joinKey(kp, key), "expected a list of 3 numbers");
        return;
      }
      for (std::size_t i = 0; i < 3; ++i) out[i] = v[i].as<double>();
    };
    triple("xyz", c.placement.xyz);
    triple("rpy_deg", c.placement.rpyDeg);
  }

  // ("model.port" or "port") => (model, port)
  static std::pair<std::string, std::string> endpoint(const std::string& text) {
    const auto dot = text.rfind('.');
    if (dot == std::string::npos) return {"", text};
    return {text.substr(0, dot), text.substr(dot + 1)};
  }

  void couplings(Instance& inst, const YAML::Node& node, const std::string& f,
                 const std::string& kp) {
    if (!node) return;
    if (!node.IsSequence()) {
      d_.error(markOf(node, f), kp, "expected a list of {from: model.port, to: model.port}");
      return;
    }
    std::size_t i = 0;
    for (const auto& c : node) {
      const std::string ckp = kp + "[" + std::to_string(i++) + "]";
      if (!c.IsMap()) {
        d_.error(markOf(c, f), ckp, "expected {from: model.port, to: model.port}");
        continue;
      }
      checkKeys(c, {"from", "to"}, f, ckp, d_);
      const YAML::Node from = c["from"], to = c["to"];
      if (!from || !to || !from.IsScalar() || !to.IsScalar()) {
        d_.error(markOf(c, f), ckp, "missing required key 'from' or 'to' (model.port)");
        continue;
      }
      auto [fm, fp] = endpoint(from.Scalar());
      auto [tm, tp] = endpoint(to.Scalar());
      const PortSpec* src = resolvePort(inst, fm, fp, from, f, joinKey(ckp, "from"));
      const PortSpec* dst = resolvePort(inst, tm, tp, to, f, joinKey(ckp, "to"));
      if (!src || !dst) continue;
      // direction: from this model's input or a component's output; to a component's input
      // or this model's output
      const bool srcOk = fm.empty() ? src->input : !src->input;
      const bool dstOk = tm.empty() ? !dst->input : dst->input;
      if (!srcOk) {
        d_.error(markOf(from, f), joinKey(ckp, "from"),
                 "'" + from.Scalar() + "' cannot send: a coupling starts at a component's "
                 "output or at this model's own input");
        continue;
      }
      if (!dstOk) {
        d_.error(markOf(to, f), joinKey(ckp, "to"),
                 "'" + to.Scalar() + "' cannot receive: a coupling ends at a component's input "
                 "or at this model's own output");
        continue;
      }
      if (src->type != dst->type) {
        d_.error(markOf(c, f), ckp,
                 "port type mismatch: '" + from.Scalar() + "' carries " + src->type + " but '" +
                     to.Scalar() + "' takes " + dst->type);
        continue;
      }
      inst.couplings.push_back({fm, fp, tm, tp, markOf(c, f)});
    }
  }

  const PortSpec* resolvePort(const Instance& inst, const std::string& model,
                              const std::string& port, const YAML::Node& where,
                              const std::string& f, const std::string& kp) {
    const Instance* owner = &inst;
    if (!model.empty()) {
      owner = inst.child(model);
      if (!owner) {
        std::vector<std::string> names;
        for (const auto& ch : inst.children) names.push_back(ch->name);
        d_.error(markOf(where, f), kp,
                 "dangling coupling: no component '" + model + "' in this model",
                 didYouMean(model, names));
        return nullptr;
      }
      if (owner->atomic() && owner->ports.empty()) return nullptr;  // its params were refused
    }
    if (const PortSpec* p = owner->port(port)) return p;
    std::vector<std::string> names;
    for (const auto& p : owner->ports) names.push_back(p.name);
    d_.error(markOf(where, f), kp,
             "dangling coupling: " +
                 (model.empty() ? std::string("this model has") : "'" + model + "' has") +
                 " no port '" + port + "'",
             didYouMean(port, names));
    return nullptr;
  }

  Diagnostics& d_;
  std::vector<fs::path> stack_;
  SceneYard yard_;  // the yard database's keys (database:, from_db, catalogue, facility)
};

}  // namespace

const Instance* Instance::child(const std::string& n) const {
  for (const auto& c : children)
    if (c->name == n) return c.get();
  return nullptr;
}

const PortSpec* Instance::port(const std::string& n) const {
  for (const auto& p : ports)
    if (p.name == n) return &p;
  return nullptr;
}

LoadResult loadScene(const fs::path& file) { return loadScene(file, {}); }

LoadResult loadScene(const fs::path& file, const ParamOverrides& overrides) {
  LoadResult r;
  using Clock = std::chrono::steady_clock;
  auto since = [](Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); };
  auto t0 = Clock::now();
  Loader loader(r.diagnostics);
  auto scene = loader.root(file, overrides);
  r.readSeconds = since(t0);
  t0 = Clock::now();
  if (scene && !r.diagnostics.hasErrors()) scene->systems = mechanicalSystems(*scene, r.diagnostics);
  if (scene && !r.diagnostics.hasErrors()) completeHookLoadChecks(*scene, r.diagnostics);
  if (scene && !r.diagnostics.hasErrors()) checkCouplingGraph(scene->root, r.diagnostics);
  if (scene && !r.diagnostics.hasErrors()) checkElementReferences(*scene, r.diagnostics);
  if (scene && !r.diagnostics.hasErrors()) bindStartRules(*scene, r.diagnostics);
  if (scene && !r.diagnostics.hasErrors()) checkStopOn(*scene, r.diagnostics);
  if (scene && !r.diagnostics.hasErrors()) checkEventsAtStart(*scene, r.diagnostics);
  if (scene && !r.diagnostics.hasErrors())
    checkResourceLimits(*scene, scene->until, "", r.diagnostics);
  if (scene && !r.diagnostics.hasErrors()) checkInitialLoops(*scene, r.diagnostics);
  r.validationSeconds = since(t0);
  t0 = Clock::now();
  if (scene && !r.diagnostics.hasErrors()) checkStiffness(*scene, r.diagnostics);
  r.stiffnessSeconds = since(t0);
  if (scene && !r.diagnostics.hasErrors()) r.scene = std::move(scene);
  return r;
}

std::unique_ptr<Scene> loadSceneOrThrow(const fs::path& file) {
  LoadResult r = loadScene(file);
  if (!r.scene) throw SceneError(std::move(r.diagnostics));
  return std::move(r.scene);
}

}  // namespace yardsim::scene
