#include "scene/mechanical_systems.hpp"

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/connected_components.hpp>
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "scene/mechanics_reader.hpp"
#include "mechanics/build.hpp"
#include "mechanics/system.hpp"
#include "dynamics/model_builder.hpp"
#include "dynamics/rotation.hpp"
#include "mechanics/build.hpp"
#include "scene/mechanics_reader.hpp"
#include "scene/provider_readers.hpp"
#include "scene/spec_reader.hpp"
#include "scene/yaml_source.hpp"

namespace yardsim::scene {

using mechanics::MechanicsSpec;
using mechanics::buildMechanics;
using mechanics::missingEnvironment;
using models::Diagnostics;
using models::ElementRef;
using models::Params;
using models::SourceMark;
using models::didYouMean;
namespace {

using dynamics::Transform;

constexpr double kDeg = M_PI / 180.0;

Transform placementTransform(const Placement& p) {
  const dynamics::Vector3 rpy(p.rpyDeg[0] * kDeg, p.rpyDeg[1] * kDeg, p.rpyDeg[2] * kDeg);
  return {dynamics::eulerToMatrix(rpy), dynamics::Vector3(p.xyz[0], p.xyz[1], p.xyz[2])};
}

std::string prefixed(const std::string& path, const std::string& name) {
  return path.empty() ? name : path + "." + name;
}

// One fragment, parsed in its own names, with where it sits.
struct Fragment {
  const Instance* owner;
  Transform X_WP;  // the instance's accumulated placement
  MechanicsSpec spec;
};

// (node, text) => the first scalar below the node (itself included) that reads the text, or an
// undefined node
YAML::Node findScalar(const YAML::Node& n, const std::string& text) {
  if (n.IsScalar()) return n.Scalar() == text ? n : YAML::Node(YAML::NodeType::Undefined);
  if (n.IsSequence())
    for (const auto& e : n)
      if (YAML::Node hit = findScalar(e, text); hit.IsDefined()) return hit;
  if (n.IsMap())
    for (auto it = n.begin(); it != n.end(); ++it)
      if (YAML::Node hit = findScalar(it->second, text); hit.IsDefined()) return hit;
  return YAML::Node(YAML::NodeType::Undefined);
}

// (fragment, section, element, name it gives) => where the fragment writes that name inside
// mechanics.<section>.<element> (the offending value), or the mechanics block when not found
SourceMark placeOf(const Fragment& f, const std::string& section, const std::string& element,
                   const std::string& value) {
  const YAML::Node& m = f.owner->mechanics;
  SourceMark where = f.owner->mechanicsWhere;
  if (!m.IsMap() || !m[section] || !m[section].IsMap() || !m[section][element]) return where;
  const YAML::Node hit = findScalar(m[section][element], value);
  if (hit.IsDefined() && !hit.Mark().is_null()) {
    where.line = hit.Mark().line + 1;
    where.column = hit.Mark().column + 1;
  }
  return where;
}

// (instance tree, accumulated placement, the root's water) => every fragment, parsed; an
// included fragment reads the root's water (its hydrodynamics solvers and door checks see the
// scene's depth, density and sea)
void collect(const Instance& inst, const Transform& X_WP, const YAML::Node& rootWater,
             std::vector<Fragment>& out, Diagnostics& diags) {
  if (inst.atomic()) return;
  if (inst.mechanics.IsDefined()) {
    Params p;
    for (const char* key : {"bodies", "ropes", "equalizers", "loops", "loads", "watch", "hydrostatics", "wind_loads",
                            "current_loads", "damping", "hydrodynamics"})
      p.set(key, inst.mechanics[key] ? inst.mechanics[key] : YAML::Node(YAML::NodeType::Map),
            inst.mechanicsWhere);
    for (const ProviderReader& reader : providerReaders())
      p.set(reader.key, inst.mechanics[reader.key] ? inst.mechanics[reader.key] : YAML::Node(YAML::NodeType::Map),
            inst.mechanicsWhere);
    // (the environment) => the root's only: one sea and one wind per scene
    for (const char* key : {"water", "wind"}) {
      const bool rootsWater = !inst.path.empty() && key == std::string("water") && rootWater;
      p.set(key,
            inst.mechanics[key] ? inst.mechanics[key]
            : rootsWater        ? rootWater
                                : YAML::Node(YAML::NodeType::Null),
            inst.mechanicsWhere);
      if (inst.mechanics[key] && !inst.path.empty())
        diags.error(inst.mechanicsWhere, joinKey(inst.keyPath, "mechanics") + "." + key,
                    std::string("only the scene root declares the ") + key +
                        " (one environment per scene); move it to the root file's mechanics");
    }
    p.set("gravity", inst.mechanics["gravity"] ? inst.mechanics["gravity"] : YAML::Load("[0, 0, -9.81]"),
          inst.mechanicsWhere);
    const std::string base = joinKey(inst.keyPath, "mechanics");
    // (system-wide settings) => read at the scene root only
    for (const char* key : {"drive_bandwidth", "drive_max_effort", "drive_tolerance", "equilibrium"}) {
      const YAML::Node n = inst.mechanics[key];
      if (!n) continue;
      if (inst.path.empty())
        p.set(key, n, inst.mechanicsWhere);
      else
        diags.error(markOf(n, inst.mechanicsWhere.file), joinKey(base, key),
                    "a system-wide setting: give it in the scene root's mechanics");
    }
    auto report = [&](const std::string& param, const YAML::Node& at, const std::string& key,
                      const std::string& msg) {
      SourceMark where = inst.mechanicsWhere;
      if (at.IsDefined() && !at.Mark().is_null()) {
        where.line = at.Mark().line + 1;
        where.column = at.Mark().column + 1;
      }
      std::string path = base + "." + param + (key.empty() ? "" : "." + key);
      // (the scene-level collision the loader put in the root's mechanics) => its keys as written
      if (inst.path.empty() && param == "collision" && key.starts_with("collision") &&
          inst.mechanics["collision"]["collision"]["_scene"])
        path = key.starts_with("collision.clearance.") ? key.substr(10) : key;
      diags.error(where, path, msg);
    };
    // bodies may be absent from a fragment that only adds ropes: skip the "at least one" rule
    if (!inst.mechanics["bodies"]) p.set("bodies", YAML::Load("{__none__: ~}"), inst.mechanicsWhere);
    MechanicsSpec spec = parseMechanics(p, [&](const std::string& param, const YAML::Node& at,
                                               const std::string& key, const std::string& msg) {
      if (key.rfind("__none__", 0) == 0) return;
      // parent, rope and loop bodies outside the fragment are resolved later, globally
      if (msg.rfind("unknown parent body", 0) == 0 || msg.rfind("unknown body", 0) == 0 ||
          msg.rfind("unknown element", 0) == 0)
        return;
      report(param, at, key, msg);
    });
    std::erase_if(spec.bodies, [](const auto& b) { return b.name == "__none__"; });
    out.push_back({&inst, X_WP, std::move(spec)});
  }
  for (const auto& child : inst.children)
    collect(*child, X_WP * placementTransform(child->placement), rootWater, out, diags);
}

}  // namespace

std::string resolveName(const std::string& from, const std::string& name,
                        const std::vector<std::string>& known) {
  if (name == "world") return name;
  std::string scope = from;
  for (;;) {
    const std::string candidate = prefixed(scope, name);
    if (std::find(known.begin(), known.end(), candidate) != known.end()) return candidate;
    if (scope.empty()) return {};
    const auto dot = scope.rfind('.');
    scope = dot == std::string::npos ? "" : scope.substr(0, dot);
  }
}

std::vector<ElementRef> systemElements(const MechanicalSystem& s) {
  std::vector<ElementRef> out;
  for (const auto& b : s.spec.bodies) {
    out.push_back({"body", b.name, ""});
    out.push_back({"joint", b.jointName, ""});
  }
  for (const auto& r : s.spec.ropes) out.push_back({"rope", r.name, ""});
  for (const auto& e : s.spec.equalizers) out.push_back({"equalizer", e.name, ""});
  for (const auto& h : s.spec.hulls) out.push_back({"hydrostatics", h.name, ""});
  for (const auto& w : s.spec.windLoads) out.push_back({"wind_load", w.name, ""});
  for (const auto& c : s.spec.currentLoads) out.push_back({"current_load", c.name, ""});
  for (const auto& d : s.spec.dampers) out.push_back({"damping", d.name, ""});
  for (const auto& h : s.spec.hydrodynamics) out.push_back({"hydrodynamics", h.name, ""});
  for (const auto& c : s.spec.providers) {
    out.push_back({c.kind, c.name, ""});
    if (c.winch) out.push_back({"rope", c.name, ""});  // (a crane rope with mass) => wire actors'
  }
  return out;
}

std::vector<std::shared_ptr<const MechanicalSystem>> mechanicalSystems(const Scene& scene,
                                                                       Diagnostics& diags) {
  std::vector<Fragment> fragments;
  const YAML::Node& root = scene.root.mechanics;
  collect(scene.root, Transform::identity(), root.IsMap() ? root["water"] : YAML::Node(), fragments,
          diags);
  if (fragments.empty() || diags.hasErrors()) return {};

  // (fragments) => bodies with full names, references resolved, placements applied
  std::vector<std::string> names;
  for (const auto& f : fragments)
    for (const auto& b : f.spec.bodies) names.push_back(prefixed(f.owner->path, b.name));
  MechanicsSpec all;
  std::vector<std::pair<SourceMark, std::string>> loopPlaces;  // parallel to all.loops
  std::vector<std::pair<SourceMark, std::string>> hydroPlaces;  // parallel to all.hydrodynamics
  if (fragments.front().owner == &scene.root) {  // the settings and the environment: the root's
    all.gravity = fragments.front().spec.gravity;
    all.settings = fragments.front().spec.settings;
    const MechanicsSpec& r = fragments.front().spec;
    all.hasWater = r.hasWater;
    all.water = r.water;
    all.waves = r.waves;
    all.current = r.current;
    all.wind = r.wind;
  }
  // (fragment, body name it writes, what names it, its section and element) => the full name, or
  // an error at the offending value
  auto resolve = [&](const Fragment& f, const std::string& name, const std::string& what,
                     const std::string& section, const std::string& element) {
    const std::string full = resolveName(f.owner->path, name, names);
    if (full.empty()) {
      std::vector<std::string> known = names;
      known.push_back("world");
      diags.error(placeOf(f, section, element, name),
                  joinKey(f.owner->keyPath, "mechanics." + section + "." + element),
                  what + " names unknown body '" + name + "'", didYouMean(name, known));
    }
    return full.empty() ? std::string("world") : full;
  };
  auto place = [](const Fragment& f, const std::string& body, const dynamics::Vector3& p) {
    return body == "world" ? dynamics::Vector3(f.X_WP.R * p + f.X_WP.p) : p;
  };
  for (const auto& f : fragments) {
    const std::string& path = f.owner->path;
    for (auto b : f.spec.bodies) {
      const std::string own = b.name;
      b.name = prefixed(path, b.name);
      b.jointName = prefixed(path, b.jointName);
      b.parent = resolve(f, b.parent, "body '" + b.name + "'", "bodies", own);
      if (b.parent == "world") b.X_PJ = f.X_WP * b.X_PJ;
      all.bodies.push_back(std::move(b));
    }
    for (auto r : f.spec.ropes) {
      const std::string own = r.name;
      r.name = prefixed(path, r.name);
      for (auto& [body, p] : r.path) {
        body = resolve(f, body, "rope '" + r.name + "'", "ropes", own);
        p = place(f, body, p);
      }
      all.ropes.push_back(std::move(r));
    }
    for (auto e : f.spec.equalizers) {
      const std::string own = e.name;
      e.name = prefixed(path, e.name);
      e.sheave.first = resolve(f, e.sheave.first, "equalizer '" + e.name + "'", "equalizers", own);
      e.sheave.second = place(f, e.sheave.first, e.sheave.second);
      for (auto& branch : e.branches)
        for (auto& [body, p] : branch) {
          body = resolve(f, body, "equalizer '" + e.name + "'", "equalizers", own);
          p = place(f, body, p);
        }
      all.equalizers.push_back(std::move(e));
    }
    for (auto l : f.spec.loads) {
      const std::string own = l.name;
      l.name = prefixed(path, l.name);
      l.body = resolve(f, l.body, "load '" + l.name + "'", "loads", own);
      all.loads.push_back(std::move(l));
    }
    // (floating providers) => full names, bodies resolved
    auto provider = [&](auto p, const char* what, const char* section) {
      const std::string own = p.name;
      p.name = prefixed(path, p.name);
      p.body = resolve(f, p.body, std::string(what) + " '" + p.name + "'", section, own);
      return p;
    };
    for (const auto& h : f.spec.hulls)
      all.hulls.push_back(provider(h, "hydrostatics", "hydrostatics"));
    for (const auto& w : f.spec.windLoads)
      all.windLoads.push_back(provider(w, "wind load", "wind_loads"));
    for (const auto& c : f.spec.currentLoads)
      all.currentLoads.push_back(provider(c, "current load", "current_loads"));
    for (const auto& d : f.spec.dampers) all.dampers.push_back(provider(d, "damping", "damping"));
    for (const auto& h : f.spec.hydrodynamics) {
      // (the entry's method value, where the fragment writes it) => the place of its problems
      SourceMark at = placeOf(f, "hydrodynamics", h.name, "impulse_response");
      if (at.line == f.owner->mechanicsWhere.line && at.column == f.owner->mechanicsWhere.column)
        at = placeOf(f, "hydrodynamics", h.name, "rankine_td");
      hydroPlaces.emplace_back(at,
                               joinKey(f.owner->keyPath, "mechanics.hydrodynamics." + h.name));
      all.hydrodynamics.push_back(provider(h, "hydrodynamics", "hydrodynamics"));
    }
    for (auto c :
         f.spec.providers) {  // (registered readers' providers) => full names, points placed
      const std::string own = c.name;
      c.name = prefixed(path, c.name);
      for (auto& [body, p] : c.attachments) {
        body = resolve(f, body, c.kind + " '" + c.name + "'", c.kind, own);
        p = place(f, body, p);
      }
      all.providers.push_back(std::move(c));
    }
    for (auto l : f.spec.loops) {
      const std::string own = l.name;
      l.name = prefixed(path, l.name);
      l.bodyA = resolve(f, l.bodyA, "loop '" + l.name + "'", "loops", own);
      l.bodyB = resolve(f, l.bodyB, "loop '" + l.name + "'", "loops", own);
      if (l.bodyA == "world") l.X_AF = f.X_WP * l.X_AF;
      if (l.bodyB == "world") l.X_BG = f.X_WP * l.X_BG;
      // (fragment, loop name) => where the loop is written (the mechanics block when not found)
      SourceMark where = f.owner->mechanicsWhere;
      const YAML::Node& m = f.owner->mechanics;
      if (const YAML::Node key = m.IsMap() ? placedEntry(m["loops"], own) : YAML::Node(YAML::NodeType::Undefined);
          key.IsDefined()) {
        where.line = key.Mark().line + 1;
        where.column = key.Mark().column + 1;
      }
      loopPlaces.emplace_back(where, joinKey(f.owner->keyPath, "mechanics.loops." + own));
      all.loops.push_back(std::move(l));
    }
  }
  // (providers that take every body with a geometry: the scene-level collision) => attachments
  for (auto& c : all.providers)
    if (c.everyBodyWithGeometry && c.attachments.empty())
      for (const auto& b : all.bodies)
        if (b.visual.shape != MechanicsSpec::Visual::Shape::Auto)
          c.attachments.push_back({b.name, dynamics::Vector3::Zero()});
  // (watches) => their elements resolved among every fragment's bodies, joints and ropes
  std::vector<std::string> elements;
  for (const auto& b : all.bodies) elements.insert(elements.end(), {b.name, b.jointName});
  for (const auto& r : all.ropes) elements.push_back(r.name);
  for (const auto& f : fragments)
    for (auto w : f.spec.watches) {
      const std::string full = resolveName(f.owner->path, w.element, elements);
      if (full.empty()) {
        // (names as the fragment would write them) => the suggestion
        std::vector<std::string> seen;
        const std::string own = f.owner->path.empty() ? "" : f.owner->path + ".";
        for (const auto& e : elements)
          seen.push_back(!own.empty() && e.starts_with(own) ? e.substr(own.size()) : e);
        diags.error(placeOf(f, "watch", w.name, w.element + "." + w.quantity),
                    joinKey(joinKey(f.owner->keyPath, "mechanics"), "watch." + w.name + ".channel"),
                    "unknown element '" + w.element + "'", didYouMean(w.element, seen));
        continue;
      }
      w.name = prefixed(f.owner->path, w.name);
      w.element = full;
      all.watches.push_back(std::move(w));
    }
  if (diags.hasErrors()) return {};

  // (joints, loops, ropes, equalizers) => connected components of the bodies (the world joins nothing)
  std::map<std::string, int> index;
  for (std::size_t i = 0; i < all.bodies.size(); ++i) index[all.bodies[i].name] = static_cast<int>(i);
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS>;
  Graph g(all.bodies.size());
  auto join = [&](const std::vector<std::string>& bodies) {
    int first = -1;
    for (const auto& b : bodies) {
      if (b == "world") continue;
      if (first < 0) first = index.at(b);
      else boost::add_edge(static_cast<std::size_t>(first), static_cast<std::size_t>(index.at(b)), g);
    }
    return first;
  };
  for (const auto& b : all.bodies) join({b.parent, b.name});
  std::vector<int> ropeAt, eqAt, loopAt;
  for (const auto& r : all.ropes) {
    std::vector<std::string> bodies;
    for (const auto& p : r.path) bodies.push_back(p.first);
    ropeAt.push_back(join(bodies));
  }
  for (const auto& e : all.equalizers) {
    std::vector<std::string> bodies{e.sheave.first};
    for (const auto& br : e.branches)
      for (const auto& p : br) bodies.push_back(p.first);
    eqAt.push_back(join(bodies));
  }
  for (const auto& l : all.loops) loopAt.push_back(join({l.bodyA, l.bodyB}));
  std::vector<int> providerAt;
  for (const auto& c : all.providers) {
    std::vector<std::string> bodies;
    for (const auto& a : c.attachments) bodies.push_back(a.first);
    providerAt.push_back(join(bodies));
  }
  // (a watch) => the system of its element's body (a joint's or a rope's first body)
  auto elementBody = [&](const std::string& e) -> int {
    for (const auto& b : all.bodies)
      if (b.name == e || b.jointName == e) return index.at(b.name);
    for (std::size_t r = 0; r < all.ropes.size(); ++r)
      if (all.ropes[r].name == e) return ropeAt[r];
    return -1;
  };
  for (std::size_t i = 0; i < all.ropes.size(); ++i)
    if (ropeAt[i] < 0)
      diags.error(scene.root.where, "mechanics", "rope '" + all.ropes[i].name + "' is attached to no body");
  for (std::size_t i = 0; i < all.equalizers.size(); ++i)
    if (eqAt[i] < 0)
      diags.error(scene.root.where, "mechanics",
                  "equalizer '" + all.equalizers[i].name + "' is attached to no body");
  for (std::size_t i = 0; i < all.providers.size(); ++i)
    if (providerAt[i] < 0)
      diags.error(scene.root.where, "mechanics",
                  all.providers[i].kind + " '" + all.providers[i].name + "' is attached to no body");
  if (const std::string missing = missingEnvironment(all); !missing.empty())
    diags.error(scene.root.where, "mechanics", missing);
  if (diags.hasErrors()) return {};
  std::vector<int> component(all.bodies.size());
  const auto count = static_cast<std::size_t>(boost::connected_components(g, component.data()));

  // (components, in order of their first body) => systems
  std::vector<std::shared_ptr<MechanicalSystem>> systems(count);
  std::vector<int> order;
  for (std::size_t i = 0; i < all.bodies.size(); ++i)
    if (std::find(order.begin(), order.end(), component[i]) == order.end()) order.push_back(component[i]);
  for (std::size_t k = 0; k < count; ++k) {
    auto& s = systems[static_cast<std::size_t>(order[k])];
    s = std::make_shared<MechanicalSystem>();
    s->name = count == 1 ? "mechanics" : "mechanics" + std::to_string(k + 1);
    s->spec.gravity = all.gravity;
    s->spec.settings = all.settings;
    s->spec.hasWater = all.hasWater;
    s->spec.water = all.water;
    s->spec.waves = all.waves;
    s->spec.current = all.current;
    s->spec.wind = all.wind;
  }
  auto systemOf = [&](int body) { return systems[static_cast<std::size_t>(component[static_cast<std::size_t>(body)])]; };
  for (std::size_t i = 0; i < all.bodies.size(); ++i) systemOf(static_cast<int>(i))->spec.bodies.push_back(all.bodies[i]);
  for (std::size_t i = 0; i < all.ropes.size(); ++i) systemOf(ropeAt[i])->spec.ropes.push_back(all.ropes[i]);
  for (std::size_t i = 0; i < all.equalizers.size(); ++i)
    systemOf(eqAt[i])->spec.equalizers.push_back(all.equalizers[i]);
  for (std::size_t i = 0; i < all.loops.size(); ++i)
    if (loopAt[i] >= 0) {
      systemOf(loopAt[i])->spec.loops.push_back(all.loops[i]);
      systemOf(loopAt[i])->loopPlaces.push_back(loopPlaces[i]);
    }
  for (const auto& l : all.loads)
    if (l.body != "world") systemOf(index.at(l.body))->spec.loads.push_back(l);
  for (std::size_t i = 0; i < all.providers.size(); ++i)
    systemOf(providerAt[i])->spec.providers.push_back(all.providers[i]);
  for (const auto& w : all.watches)
    if (const int b = elementBody(w.element); b >= 0) systemOf(b)->spec.watches.push_back(w);
  // (floating providers) => the system of their body (a world body was reported above)
  auto on = [&](const std::string& body) { return systemOf(index.count(body) ? index.at(body) : 0); };
  for (const auto& h : all.hulls) on(h.body)->spec.hulls.push_back(h);
  for (const auto& w : all.windLoads) on(w.body)->spec.windLoads.push_back(w);
  for (const auto& c : all.currentLoads) on(c.body)->spec.currentLoads.push_back(c);
  for (const auto& d : all.dampers) on(d.body)->spec.dampers.push_back(d);
  for (std::size_t i = 0; i < all.hydrodynamics.size(); ++i) {
    const auto s = on(all.hydrodynamics[i].body);
    s->spec.hydrodynamics.push_back(all.hydrodynamics[i]);
    s->hydroPlaces.push_back(hydroPlaces[i]);
    // (the scene's one sea, the root's) => what the entry cannot take, at the entry
    if (const auto& seaCheck = all.hydrodynamics[i].seaCheck)
      for (const std::string& problem : seaCheck(forces::AiryWaves(all.water, all.waves)))
        diags.error(hydroPlaces[i].first, hydroPlaces[i].second, problem);
  }

  // (message naming "body 'x'") => where that body's added_mass (or else its first value) is
  // written, and its key path; the root otherwise
  auto bodyPlace = [&](const std::string& message) -> std::pair<SourceMark, std::string> {
    const auto at = message.find("body '");
    const auto end = at == std::string::npos ? at : message.find('\'', at + 6);
    if (end != std::string::npos) {
      const std::string full = message.substr(at + 6, end - at - 6);
      for (const auto& f : fragments)
        for (const auto& b : f.spec.bodies) {
          const YAML::Node& m = f.owner->mechanics;
          if (prefixed(f.owner->path, b.name) != full || !m.IsMap() || !m["bodies"] ||
              !m["bodies"][b.name])
            continue;
          const YAML::Node body = m["bodies"][b.name];
          const bool am = message.find("added mass") != std::string::npos && body["added_mass"];
          const YAML::Node n = spec::Reader::marked(am ? body["added_mass"] : body);
          const std::string key =
              joinKey(f.owner->keyPath, "mechanics.bodies." + b.name + (am ? ".added_mass" : ""));
          if (n.IsDefined() && !n.Mark().is_null())
            return {{f.owner->mechanicsWhere.file, n.Mark().line + 1, n.Mark().column + 1}, key};
          return {f.owner->mechanicsWhere, key};
        }
    }
    return {scene.root.where, "mechanics"};
  };
  std::vector<std::shared_ptr<const MechanicalSystem>> out;
  for (auto& s : systems) {
    try {
      // (spec) => built once, with the kernel's own checks (inertia, tree) naming the body
      s->built = std::make_shared<const mechanics::BuiltMechanics>(buildMechanics(s->spec));
      // (providers built from the whole system: collision sets) => built once here, so that a
      // name that matches nothing or a shape the kernel refuses is reported before the run
      if (std::any_of(s->spec.providers.begin(), s->spec.providers.end(),
                      [](const auto& p) { return bool(p.buildFromSystem); }))
        mechanics::System(*s->built, {}, s->name);
    } catch (const ProviderPlaceError& e) {
      // (a provider's problem at a node of its entry) => the fragment that declared it
      SourceMark where = scene.root.where;
      std::string key = e.key;
      for (const auto& f : fragments)
        for (const auto& p : f.spec.providers)
          if (prefixed(f.owner->path, p.name) == e.provider) {
            where = f.owner->mechanicsWhere;
            if (e.line > 0) where = {where.file, e.line, e.column};
            if (!e.rootKey) key = joinKey(f.owner->keyPath, "mechanics." + p.kind + "." + e.key);
          }
      diags.error(where, key, std::string("mechanical system '") + s->name + "': " + e.what());
    } catch (const std::exception& e) {
      const auto [where, key] = bodyPlace(e.what());
      diags.error(where, key, std::string("mechanical system '") + s->name + "': " + e.what());
    }
    if (scene.root.child(s->name))
      diags.error(scene.root.where, "components." + s->name,
                  "the name '" + s->name + "' is taken by the scene's mechanical system; rename this component");
    out.push_back(s);
  }
  if (!out.empty() && !(scene.dt > 0))
    diags.error(scene.root.where, "integrator",
                "the scene has mechanics: give the integrator and its step, e.g. integrator: {method: rk4, dt: 0.01}");
  return out;
}

}  // namespace yardsim::scene
