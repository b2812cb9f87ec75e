// The `collision:` key of a `mechanics:` block (docs/collision.md), and the scene-level
// `collision:` / `clearance:` that the loader turns into one such entry named `collision` (every
// body with a geometry unless `bodies:` lists them; watch channels `<watch>.distance`, events on
// element `<watch>`): one entry is one collision set of a mechanical system — the bodies that touch
// (each body's `geometry` is its collision shape unless `shapes:` gives another), an optional
// ground, materials and the contact law of each material pair (forces/contact.hpp, evaluated at
// every integrator stage), ignored pairs, and clearance watches between bodies and ropes
// (collision/body_collision.hpp). Channels: <name>.points, <name>.normal_force, <name>.<body>.fz
// per body, <name>.<watch>.distance per watch, and <name>.energy / <name>.power like every
// provider.
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>

#include "collision/collision_set.hpp"
#include "dynamics/kinematics.hpp"
#include "forces/contact.hpp"
#include "forces/geometry/triangle_mesh.hpp"
#include "scene/provider_readers.hpp"
#include "scene/providers/reader_support.hpp"

namespace yardsim::scene::providers {

namespace {

using mechanics::BuiltMechanics;
using mechanics::MechanicsSpec;

// m: the linear law's damping ramp unless given: none, the plain law (docs/collision.md "Stiff
// contact")
constexpr double kDefaultDampingDepth = 0.0;

// A clearance watch as written: patterns of body or rope names (`*` matches any run of
// characters), the threshold, how far distances are computed, and where it was written.
struct WatchSpec {
  std::string name;
  std::vector<std::string> a, b;
  double below = 0.0, range = 0.0;
  int line = 0, column = 0;  // of `between`
};

// Where a name was written (1-based line and column) and its key below the entry.
struct NamePlace {
  int line = 0, column = 0;
  std::string key;
};

// Everything an entry says, read at the door; resolved against the built system later.
struct CollisionSpec {
  std::vector<std::string> bodies;
  std::map<std::string, collision::Shape> shapes;  // separate collision shapes, centred on B
  bool ground = false;
  double groundHeight = 0.0;                            // m, world z of the ground plane
  std::map<std::string, std::string> materials;         // body or "ground" => material name
  std::map<std::string, forces::ContactMaterial> laws;  // "a/b" (sorted) or "default"
  std::vector<std::pair<std::string, std::string>> ignore;
  std::vector<WatchSpec> watches;
  int pointsPerPair = 4;
  double ropeDiameter = 0.04;  // m, the capsules of ropes that give no diameter of their own
  // the scene-level form (`collision:` / `clearance:` at the root, the loader's `_scene`): the
  // bodies default to every body with a geometry, watch channels and events are `<watch>`, and
  // without `collision:` (only `clearance:`) there is no contact
  bool sceneLevel = false, contact = true;
  std::string keyRoot;  // what keys start with in messages: "<set>" or "collision"
  // names given under shapes, materials and ignore, where: checked against the bodies once they
  // are known (at the door for a listed set, when the system is built for a scene-level one)
  std::vector<std::pair<std::string, NamePlace>> named;
  std::vector<NamePlace> bodyPlaces;  // per listed body
  NamePlace place;                    // the entry's
};

// (node) => its 1-based line and column
NamePlace placeOf(const YAML::Node& n, std::string key) {
  const YAML::Node m = spec::Reader::marked(n);
  return {m.Mark().line + 1, m.Mark().column + 1, std::move(key)};
}

// (name, pattern with `*`) => whether the pattern matches the whole name
bool matches(const std::string& name, const std::string& pattern) {
  std::size_t n = 0, p = 0, star = std::string::npos, mark = 0;
  while (n < name.size()) {
    if (p < pattern.size() && pattern[p] == name[n]) {
      ++n;
      ++p;
    } else if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      mark = n;
    } else if (star != std::string::npos) {
      p = star + 1;
      n = ++mark;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

// ({box: [lx, ly, lz]} | {sphere: r} | {cylinder: {radius, length}} | {capsule: {radius,
// length}}) => the shape; every size must be > 0 m
collision::Shape readShape(const spec::Reader& r, const YAML::Node& n, const std::string& key) {
  const char* expected =
      "expected one of {box: [lx, ly, lz]}, {sphere: r}, "
      "{cylinder: {radius, length}}, {capsule: {radius, length}} (m, > 0)";
  if (!n.IsMap() || n.size() != 1) {
    r.fail(n, key, expected);
    return collision::Shape::sphere(1.0);
  }
  if (!r.keys(n, {"box", "sphere", "cylinder", "capsule"}, key))
    return collision::Shape::sphere(1.0);
  auto positive = [&](const YAML::Node& at, const std::string& k) {
    const double v = r.number(at, k, 1.0, true);
    if (at && !(v > 0)) r.fail(at, k, "must be > 0 m, got " + std::to_string(v));
    return v > 0 ? v : 1.0;
  };
  if (const YAML::Node b = n["box"]) {
    const dynamics::Vector3 size = r.length3(b, key + ".box", dynamics::Vector3::Ones());
    if (!(size.minCoeff() > 0)) r.fail(b, key + ".box", "every edge must be > 0 m");
    return collision::Shape::box(size.cwiseMax(1e-9));
  }
  if (const YAML::Node s = n["sphere"])
    return collision::Shape::sphere(positive(s, key + ".sphere"));
  const bool cyl = bool(n["cylinder"]);
  YAML::Node c = cyl ? n["cylinder"] : n["capsule"];
  const std::string k = key + (cyl ? ".cylinder" : ".capsule");
  if (!r.keys(c, {"radius", "length"}, k)) return collision::Shape::sphere(1.0);
  const double radius = positive(c["radius"], k + ".radius");
  const double length = positive(c["length"], k + ".length");
  return cyl ? collision::Shape::cylinder(radius, length)
             : collision::Shape::capsule(radius, length);
}

// ({law: hunt_crossley | linear, k, n, c | restitution + impact_speed, damping_depth, mu,
// slip_speed, friction: sqrt | tanh}) => the pair's contact material
forces::ContactMaterial readLaw(const spec::Reader& r, const YAML::Node& n,
                                const std::string& key) {
  forces::ContactMaterial m;
  if (!r.keys(n,
              {"law", "k", "n", "c", "restitution", "impact_speed", "damping_depth", "mu",
               "slip_speed", "friction"},
              key))
    return m;
  const std::string law = n["law"] && n["law"].IsScalar() ? n["law"].Scalar() : "hunt_crossley";
  if (law != "hunt_crossley" && law != "linear")
    r.fail(n["law"], key + ".law", "expected hunt_crossley or linear, got '" + law + "'");
  m.law.kind =
      law == "linear" ? forces::NormalLawKind::kLinear : forces::NormalLawKind::kHuntCrossley;
  m.law.stiffness = r.number(n["k"], key + ".k", 1.0, true);
  if (n["k"] && !(m.law.stiffness > 0)) r.fail(n["k"], key + ".k", "must be > 0 (N/m^n)");
  m.law.exponent = r.number(n["n"], key + ".n", law == "linear" ? 1.0 : 1.5);
  if (!(m.law.exponent >= 1.0)) r.fail(n["n"], key + ".n", "must be >= 1");
  if (n["c"] && n["restitution"])
    r.fail(n["restitution"], key + ".restitution", "give either c or restitution");
  m.law.damping = nonNegative(r, n["c"], key + ".c", 0.0);
  if (const YAML::Node e = n["restitution"]) {  // (e, v0) => Lankarani-Nikravesh damping
    const double rest = r.number(e, key + ".restitution", 1.0);
    const double v0 = r.number(n["impact_speed"], key + ".impact_speed", 1.0, true);
    if (!(rest > 0 && rest <= 1))
      r.fail(e, key + ".restitution", "must be in (0, 1]");
    else if (law == "linear")
      r.fail(e, key + ".restitution",
             "restitution sets a Hunt-Crossley law's c; give c for the linear law");
    else if (v0 > 0)
      m.law.damping = forces::lankaraniNikraveshDamping(m.law.stiffness, rest, v0);
    if (n["impact_speed"] && !(v0 > 0))
      r.fail(n["impact_speed"], key + ".impact_speed", "must be > 0 m/s");
  }
  if (law == "linear") {  // the damping's ramp, m (docs/collision.md "The contact law")
    m.law.dampingDepth =
        nonNegative(r, n["damping_depth"], key + ".damping_depth", kDefaultDampingDepth);
  } else if (n["damping_depth"]) {
    r.fail(n["damping_depth"], key + ".damping_depth",
           "the linear law's damping ramp (Hunt-Crossley's damping is continuous already)");
  }
  m.friction.mu = nonNegative(r, n["mu"], key + ".mu", 0.0);
  m.friction.slipSpeed = r.number(n["slip_speed"], key + ".slip_speed", 1e-3);
  if (!(m.friction.slipSpeed > 0)) r.fail(n["slip_speed"], key + ".slip_speed", "must be > 0 m/s");
  const std::string form =
      n["friction"] && n["friction"].IsScalar() ? n["friction"].Scalar() : "sqrt";
  if (form != "sqrt" && form != "tanh")
    r.fail(n["friction"], key + ".friction", "expected sqrt or tanh, got '" + form + "'");
  m.friction.form = form == "tanh" ? forces::FrictionForm::kTanh : forces::FrictionForm::kSqrt;
  return m;
}

// (node, key) => a list of names
std::vector<std::string> names(const spec::Reader& r, const YAML::Node& n, const std::string& key) {
  std::vector<std::string> out;
  if (!n.IsSequence()) {
    r.fail(n, key, "expected a list of names");
    return out;
  }
  for (std::size_t i = 0; i < n.size(); ++i) {
    if (n[i].IsScalar())
      out.push_back(n[i].Scalar());
    else
      r.fail(n[i], key + "[" + std::to_string(i) + "]", "expected a name");
  }
  return out;
}

// (entry) => what it says, every problem reported at its node
CollisionSpec readEntry(const YAML::Node& n, const spec::Reader& r, const std::string& key) {
  CollisionSpec c;
  c.keyRoot = key;
  if (const YAML::Node scene = n["_scene"]) {  // (the loader's mark) => the scene-level form
    c.sceneLevel = true;
    c.contact = scene.Scalar() == "contact";
  }
  if (!r.keys(n,
              {"bodies", "shapes", "ground", "materials", "contact", "ignore", "clearance",
               "points_per_pair", "rope_diameter", "_scene"},
              key))
    return c;
  c.place = placeOf(n, key);
  if (n["bodies"]) {
    c.bodies = names(r, n["bodies"], key + ".bodies");
    for (std::size_t i = 0; i < c.bodies.size(); ++i)
      c.bodyPlaces.push_back(placeOf(n["bodies"][i], key + ".bodies[" + std::to_string(i) + "]"));
  } else if (!c.sceneLevel)
    r.fail(n, key, "missing required key 'bodies' (the bodies that touch: [a, b, ...])");
  // (a name under shapes, materials or ignore) => checked now against listed bodies, or kept
  auto member = [&](const std::string& b, const YAML::Node& at, const std::string& k,
                    bool groundToo) {
    if (groundToo && b == "ground") return;
    if (c.sceneLevel && !n["bodies"]) {
      c.named.emplace_back(b, placeOf(at, k));
      return;
    }
    if (std::find(c.bodies.begin(), c.bodies.end(), b) == c.bodies.end())
      r.fail(at, k, "'" + b + "' is not one of bodies" + (groundToo ? " (or ground)" : ""));
  };
  if (const YAML::Node s = n["shapes"]) {
    if (!s.IsMap())
      r.fail(s, key + ".shapes", "expected {body: shape, ...}");
    else
      for (auto it = s.begin(); it != s.end(); ++it) {
        const std::string b = it->first.as<std::string>();
        c.shapes.emplace(b, readShape(r, it->second, key + ".shapes." + b));
        member(b, it->first, key + ".shapes." + b, false);
      }
  }
  if (const YAML::Node g = n["ground"]) {  // (ground: z) => the half-space below z (world)
    c.ground = true;
    c.groundHeight = r.number(g, key + ".ground", 0.0);
  }
  if (const YAML::Node m = n["materials"]) {
    if (!m.IsMap())
      r.fail(m, key + ".materials", "expected {body | ground: material name, ...}");
    else
      for (auto it = m.begin(); it != m.end(); ++it) {
        const std::string b = it->first.as<std::string>();
        member(b, it->first, key + ".materials." + b, true);
        if (it->second.IsScalar())
          c.materials[b] = it->second.Scalar();
        else
          r.fail(it->second, key + ".materials." + b, "expected a material name");
      }
  }
  const YAML::Node laws = n["contact"];
  if (!c.contact) {  // (only `clearance:` at the scene root) => no contact, no law
    c.laws["default"] = {};
  } else if (!laws || !laws.IsMap() || !laws["default"]) {
    r.fail(laws ? laws : n, key + ".contact",
           "expected {default: {law, k, ...}, material_a/material_b: {...}, ...} with a default");
  } else {
    for (auto it = laws.begin(); it != laws.end(); ++it) {
      std::string pair = it->first.as<std::string>();
      const auto slash = pair.find('/');
      if (pair != "default" && slash == std::string::npos) {
        r.fail(it->first, key + ".contact." + pair,
               "expected default or a pair material_a/material_b");
        continue;
      }
      if (slash != std::string::npos && pair.substr(0, slash) > pair.substr(slash + 1))
        pair = pair.substr(slash + 1) + "/" + pair.substr(0, slash);
      c.laws[pair] = readLaw(r, it->second, key + ".contact." + it->first.as<std::string>());
    }
  }
  if (const YAML::Node ig = n["ignore"]) {
    if (!ig.IsSequence())
      r.fail(ig, key + ".ignore", "expected a list of pairs [[a, b], ...]");
    else
      for (std::size_t i = 0; i < ig.size(); ++i) {
        const auto pair = names(r, ig[i], key + ".ignore[" + std::to_string(i) + "]");
        if (pair.size() != 2) {
          r.fail(ig[i], key + ".ignore[" + std::to_string(i) + "]", "expected a pair [a, b]");
          continue;
        }
        for (const auto& b : pair)
          member(b, ig[i], key + ".ignore[" + std::to_string(i) + "]", true);
        c.ignore.emplace_back(pair[0], pair[1]);
      }
  }
  if (const YAML::Node p = n["points_per_pair"]) {
    c.pointsPerPair = static_cast<int>(r.number(p, key + ".points_per_pair", 4.0));
    if (c.pointsPerPair < 1) r.fail(p, key + ".points_per_pair", "must be >= 1");
  }
  const double ropeDiameter = nonNegative(r, n["rope_diameter"], key + ".rope_diameter", 0.04);
  if (const YAML::Node w = n["clearance"]) {  // (name: {between: [a, b], below, range}) => watches
    if (!w.IsMap())
      r.fail(w, key + ".clearance", "expected {name: {between: [a, b], below: m}}");
    else
      for (auto it = w.begin(); it != w.end(); ++it) {
        WatchSpec ws;
        ws.name = it->first.as<std::string>();
        const std::string k = key + ".clearance." + ws.name;
        const YAML::Node e = it->second;
        if (!r.keys(e, {"between", "below", "range"}, k)) continue;
        const YAML::Node between = e["between"];
        if (!between || !between.IsSequence() || between.size() != 2) {
          r.fail(between ? between : e, k + ".between",
                 "expected two names or patterns [a, b] (bodies or ropes, * matches any run)");
          continue;
        }
        // (one side: a name, a pattern or a list of them) => its names
        auto side = [&](std::size_t i) {
          if (between[i].IsSequence()) return names(r, between[i], k + ".between");
          if (between[i].IsScalar()) return std::vector<std::string>{between[i].Scalar()};
          r.fail(between[i], k + ".between", "expected a name, a pattern or a list of them");
          return std::vector<std::string>{};
        };
        ws.a = side(0);
        ws.b = side(1);
        ws.below = nonNegative(r, e["below"], k + ".below", 0.0, true);
        ws.range = nonNegative(r, e["range"], k + ".range", ws.below);
        const NamePlace at = placeOf(between, k + ".between");
        ws.line = at.line;
        ws.column = at.column;
        c.watches.push_back(std::move(ws));
      }
  }
  c.ropeDiameter = ropeDiameter;
  return c;
}

// (a body's geometry) => its collision shape at X_BS; false when it has none (Auto)
bool shapeOf(const MechanicsSpec::Visual& v, const dynamics::SpatialInertia& in,
             collision::Shape& shape, dynamics::Transform& X_BS) {
  using S = MechanicsSpec::Visual::Shape;
  X_BS = v.posed ? v.X_BG : dynamics::Transform{dynamics::Matrix3::Identity(), in.com};
  switch (v.shape) {
    case S::Box:
      shape = collision::Shape::box(v.size);
      return true;
    case S::Cylinder:
      shape = collision::Shape::cylinder(v.size[0], v.size[1]);
      return true;
    case S::Sphere:
      shape = collision::Shape::sphere(v.size[0]);
      return true;
    case S::Mesh:
      forces::checkClosedMesh(*v.mesh);  // contact depths need a closed surface
      shape = collision::Shape::triangleMesh(v.mesh);
      return true;
    default:
      return false;
  }
}

// (what the entry says, its provider name, the built system, attachments = its bodies) => the
// collision set's contact provider with its channels; ProviderPlaceError at the entry's node for
// a name that matches nothing, a body without a usable shape or a shape the kernel refuses
std::unique_ptr<forces::ForceProvider> build(const CollisionSpec& c, const std::string& name,
                                             const BuiltMechanics& mech,
                                             const std::vector<forces::Attachment>& at) {
  const dynamics::Model& model = mech.model;
  const std::string prefix = name.substr(0, name.rfind('.') + 1);  // the fragment's path
  // (message, where and which key) => the problem at its place in the file
  auto fail = [&](const std::string& msg, int line, int column, const std::string& key) {
    throw scene::ProviderPlaceError("collision '" + name + "': " + msg, name, line, column,
                                    c.sceneLevel && key.starts_with(c.keyRoot + ".clearance.")
                                        ? key.substr(c.keyRoot.size() + 1)
                                        : key,
                                    c.sceneLevel);
  };
  // (the bodies: as listed, or every body with a geometry by its full name) => per attachment
  std::vector<std::string> bodies = c.bodies;
  if (bodies.empty())
    for (const auto& a : at) bodies.push_back(model.names[static_cast<std::size_t>(a.body)]);
  for (const auto& [b, where] : c.named)  // (names under shapes, materials, ignore) => bodies
    if (std::find(bodies.begin(), bodies.end(), b) == bodies.end())
      fail("'" + b + "' is not a body with a geometry", where.line, where.column, where.key);
  collision::BodyCollisionSpec spec;
  spec.bodyCount = model.nbodies;
  spec.maxPointsPerPair = c.pointsPerPair;
  spec.contact = c.contact;
  // (materials) => names, the pair table from the laws
  std::vector<std::string> materialNames{"default"};
  auto materialOf = [&](const std::string& body) {
    const auto it = c.materials.find(body);
    const std::string m = it == c.materials.end() ? "default" : it->second;
    const auto found = std::find(materialNames.begin(), materialNames.end(), m);
    if (found != materialNames.end()) return static_cast<int>(found - materialNames.begin());
    materialNames.push_back(m);
    return static_cast<int>(materialNames.size() - 1);
  };
  std::vector<std::pair<std::string, int>> reactions;  // (name as written, body index)
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const int body = at.at(i).body;
    const auto& visual = mech.visuals.at(static_cast<std::size_t>(body));
    collision::BodyShape s{
        body, model.names[static_cast<std::size_t>(body)], {}, {}, materialOf(bodies[i])};
    if (const auto it = c.shapes.find(bodies[i]); it != c.shapes.end()) {
      s.shape = it->second;
      s.X_BS = {dynamics::Matrix3::Identity(), model.inertias[static_cast<std::size_t>(body)].com};
    } else {
      try {
        if (!shapeOf(visual, model.inertias[static_cast<std::size_t>(body)], s.shape, s.X_BS))
          fail("body '" + bodies[i] + "' has no geometry: give it one, or a shape under shapes:",
               c.bodyPlaces.at(i).line, c.bodyPlaces.at(i).column, c.bodyPlaces.at(i).key);
      } catch (const forces::MeshError& e) {
        throw std::invalid_argument("collision '" + name + "': body '" + bodies[i] +
                                    "': its mesh cannot be used for contact: " + e.what());
      }
    }
    spec.shapes.push_back(std::move(s));
    reactions.emplace_back(bodies[i], body);
  }
  spec.ground = c.ground;
  spec.groundHeight = c.groundHeight;
  spec.groundMaterial = materialOf("ground");
  const int nm = static_cast<int>(materialNames.size());
  std::vector<forces::ContactMaterial> laws{c.laws.at("default")};
  spec.materialCount = nm;
  spec.pairLaw.assign(static_cast<std::size_t>(nm * nm), 0);
  for (int a = 0; a < nm; ++a)
    for (int b = 0; b < nm; ++b) {
      const std::string& x = materialNames[static_cast<std::size_t>(std::min(a, b))];
      const std::string& y = materialNames[static_cast<std::size_t>(std::max(a, b))];
      const auto it = c.laws.find(std::min(x, y) + "/" + std::max(x, y));
      if (it == c.laws.end()) continue;
      laws.push_back(it->second);
      spec.pairLaw[static_cast<std::size_t>(a * nm + b)] = static_cast<int>(laws.size() - 1);
    }
  // (joints, the scene's ignore list) => pairs never tested: a body and its parent unless free
  for (int i = 1; i < model.nbodies; ++i)
    if (model.jointNv[static_cast<std::size_t>(i)] != 6)
      spec.ignore.emplace_back(i, model.parent[static_cast<std::size_t>(i)]);
  auto indexOf = [&](const std::string& n) {
    if (n == "ground") return 0;
    const auto it = std::find(bodies.begin(), bodies.end(), n);
    return at.at(static_cast<std::size_t>(it - bodies.begin())).body;
  };
  for (const auto& [a, b] : c.ignore) spec.ignore.emplace_back(indexOf(a), indexOf(b));
  // (ropes, and each branch of an equalizer from its sheave) => capsules with their own diameter
  // (the set's rope_diameter when they give none); only those a watch names are built
  auto bodyOf = [&](const std::string& b) { return b == "world" ? 0 : model.bodyIndex(b); };
  for (const auto& r : mech.ropes) {
    collision::RopeShape rope{
        r.name, {}, r.material.diameter > 0 ? r.material.diameter : c.ropeDiameter};
    for (const auto& [body, p] : r.path) rope.path.emplace_back(bodyOf(body), p);
    spec.ropes.push_back(std::move(rope));
  }
  for (const auto& e : mech.equalizers)
    for (const auto& branch : e.branches) {
      collision::RopeShape rope{
          e.name, {}, e.material.diameter > 0 ? e.material.diameter : c.ropeDiameter};
      rope.path.emplace_back(bodyOf(e.sheave.first), e.sheave.second);
      for (const auto& [body, p] : branch) rope.path.emplace_back(bodyOf(body), p);
      spec.ropes.push_back(std::move(rope));
    }
  for (const WatchSpec& w : c.watches) {
    collision::ClearanceSpec cs{w.name, {}, {}, {}, {}, w.below, w.range};
    auto side = [&](const std::vector<std::string>& patterns, std::vector<int>& shapes,
                    std::vector<int>& ropes) {
      for (const std::string& p : patterns) {
        const std::size_t before = shapes.size() + ropes.size();
        for (std::size_t i = 0; i < spec.shapes.size(); ++i)
          if (matches(spec.shapes[i].name, p) || matches(spec.shapes[i].name, prefix + p))
            shapes.push_back(static_cast<int>(i));
        for (std::size_t i = 0; i < spec.ropes.size(); ++i)
          if (matches(spec.ropes[i].name, p) || matches(spec.ropes[i].name, prefix + p))
            ropes.push_back(static_cast<int>(i));
        if (shapes.size() + ropes.size() == before)
          fail("clearance '" + w.name + "': '" + p + "' matches no body" +
                   (c.sceneLevel && c.bodies.empty() ? " with a geometry" : " of bodies:") +
                   ", no rope and no equalizer",
               w.line, w.column, c.keyRoot + ".clearance." + w.name + ".between");
      }
    };
    side(w.a, cs.shapesA, cs.ropesA);
    side(w.b, cs.shapesB, cs.ropesB);
    spec.watches.push_back(std::move(cs));
  }
  dynamics::Data kin(model);
  dynamics::forwardKinematics(model, kin, mech.q0, mech.v0);
  std::shared_ptr<collision::BodyCollision> world;
  try {
    world = std::make_shared<collision::BodyCollision>(std::move(spec), kin);
  } catch (const collision::CollisionError& e) {
    fail(e.what(), c.place.line, c.place.column, c.place.key);
  }
  collision::CollisionSet::Options options;
  options.contact = c.contact;
  options.watchesAtTop = c.sceneLevel;
  if (!c.contact) reactions.clear();
  return std::make_unique<collision::CollisionSet>(name, std::move(world), std::move(laws),
                                                   reactions, options);
}

}  // namespace

YARDSIM_REGISTER_PROVIDER(
    collisionSets,
    ProviderReader{
        .key = "collision",
        .summary =
            "name: {bodies: [a, b], ground: z, shapes, materials, contact: {default: {law, k, "
            "n, c | restitution, mu}}, ignore: [[a, b]], clearance: {w: {between: [a, b], "
            "below: m}}}",
        .read = [](const std::string&, const YAML::Node& n, const spec::Reader& r,
                   const std::string& key) {
          MechanicsSpec::ProviderSpec out;
          const CollisionSpec c = readEntry(n, r, key);
          for (const auto& b : c.bodies) out.attachments.push_back({b, dynamics::Vector3::Zero()});
          out.everyBodyWithGeometry = c.sceneLevel && c.bodies.empty();
          out.buildFromSystem = [c](const std::string& name, const BuiltMechanics& mech,
                                    const std::vector<forces::Attachment>& at) {
            return build(c, name, mech, at);
          };
          return out;
        }});

}  // namespace yardsim::scene::providers
