// Reading one `collision:` entry at the door (collision_entry.hpp): shapes, contact laws, names,
// watches; every problem at its node.
#include "scene/providers/collision_entry.hpp"

#include <algorithm>

#include "forces/contact_law.hpp"
#include "scene/providers/reader_support.hpp"

namespace yardsim::scene::providers {

namespace {

// m: the linear law's damping ramp unless given: none, the plain law (docs/collision.md "Stiff
// contact")
constexpr double kDefaultDampingDepth = 0.0;
// groups a set can name: the kernel's 32 group bits less bit 0 (what no group holds)
constexpr std::size_t kMaxGroups = 31;

// (a mapping's entry) => the node to report it at: its key, or its value when the key has no
// place (the loader rebuilds mappings while resolving $references, and keys lose their marks)
YAML::Node keyNode(const YAML::const_iterator& it) {
  return it->first.Mark().is_null() ? it->second : it->first;
}

// (mapping, name, key path) => a required number of it: missing, reported at the mapping
double required(const spec::Reader& r, const YAML::Node& map, const char* name,
                const std::string& key, double fallback) {
  if (!map[name]) {
    r.fail(map, key, std::string("missing required key '") + name + "' (a number)");
    return fallback;
  }
  return r.number(map[name], key + "." + name, fallback);
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
  // (mapping, its key, name) => the number under name, > 0 m
  auto positive = [&](const YAML::Node& map, const std::string& k, const char* name) {
    const double v = required(r, map, name, k, 1.0);
    if (map[name] && !(v > 0))
      r.fail(map[name], k + "." + name, "must be > 0 m, got " + std::to_string(v));
    return v > 0 ? v : 1.0;
  };
  if (const YAML::Node b = n["box"]) {
    const dynamics::Vector3 size = r.length3(b, key + ".box", dynamics::Vector3::Ones());
    if (!(size.minCoeff() > 0)) r.fail(b, key + ".box", "every edge must be > 0 m");
    return collision::Shape::box(size.cwiseMax(1e-9));
  }
  if (n["sphere"]) return collision::Shape::sphere(positive(n, key, "sphere"));
  const bool cyl = bool(n["cylinder"]);
  YAML::Node c = cyl ? n["cylinder"] : n["capsule"];
  const std::string k = key + (cyl ? ".cylinder" : ".capsule");
  if (!r.keys(c, {"radius", "length"}, k)) return collision::Shape::sphere(1.0);
  const double radius = positive(c, k, "radius");
  const double length = positive(c, k, "length");
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
  m.law.stiffness = required(r, n, "k", key, 1.0);
  if (n["k"] && !(m.law.stiffness > 0)) r.fail(n["k"], key + ".k", "must be > 0 (N/m^n)");
  m.law.exponent = r.number(n["n"], key + ".n", law == "linear" ? 1.0 : 1.5);
  if (!(m.law.exponent >= 1.0)) r.fail(n["n"], key + ".n", "must be >= 1");
  if (n["c"] && n["restitution"])
    r.fail(n["restitution"], key + ".restitution", "give either c or restitution");
  m.law.damping = nonNegative(r, n["c"], key + ".c", 0.0);
  if (const YAML::Node e = n["restitution"]) {  // (e, v0) => Lankarani-Nikravesh damping
    const double rest = r.number(e, key + ".restitution", 1.0);
    const double v0 = required(r, n, "impact_speed", key, 1.0);
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

// (entry) => its `groups: {name: [patterns], ...}` into c.groups: at most 31 (one bit each of
// the kernel's 32-bit groups, bit 0 for what no group holds); a name of a listed body or
// `ground` is refused (an ignore pair must say which it means)
void readGroups(const YAML::Node& n, const spec::Reader& r, const std::string& key,
                CollisionSpec& c) {
  const YAML::Node g = n["groups"];
  if (!g) return;
  if (!g.IsMap()) {
    r.fail(g, key + ".groups", "expected {group: [body or rope names or patterns], ...}");
    return;
  }
  for (auto it = g.begin(); it != g.end(); ++it) {
    GroupSpec group;
    group.name = it->first.as<std::string>();
    const std::string k = key + ".groups." + group.name;
    group.place = placeOf(keyNode(it), k);
    if (c.groups.size() == kMaxGroups) {
      r.fail(keyNode(it), k, "at most " + std::to_string(kMaxGroups) + " groups");
      return;
    }
    if (group.name == "ground" ||
        std::find(c.bodies.begin(), c.bodies.end(), group.name) != c.bodies.end()) {
      r.fail(keyNode(it), k,
             "group '" + group.name + "' has the name of a body or of the ground: give it another");
      continue;
    }
    group.patterns = names(r, it->second, k);
    for (std::size_t i = 0; i < group.patterns.size(); ++i)
      group.places.push_back(placeOf(it->second[i], k + "[" + std::to_string(i) + "]"));
    c.groups.push_back(std::move(group));
  }
}

}  // namespace

int groupIndex(const CollisionSpec& c, const std::string& name) {
  for (std::size_t i = 0; i < c.groups.size(); ++i)
    if (c.groups[i].name == name) return static_cast<int>(i);
  return -1;
}

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

// (entry) => what it says, every problem reported at its node
CollisionSpec readEntry(const YAML::Node& n, const spec::Reader& r, const std::string& key) {
  CollisionSpec c;
  c.keyRoot = key;
  if (const YAML::Node scene = n["_scene"]) {  // (the loader's mark) => the scene-level form
    c.sceneLevel = true;
    c.contact = scene.Scalar() == "contact";
  }
  if (!r.keys(n,
              {"bodies", "shapes", "ground", "materials", "contact", "ignore", "groups",
               "clearance", "points_per_pair", "rope_diameter", "_scene"},
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
                    bool groundToo, bool groupToo = false) {
    if (groundToo && b == "ground") return;
    if (groupToo && groupIndex(c, b) >= 0) return;
    if (c.sceneLevel && !n["bodies"]) {
      c.named.emplace_back(b, placeOf(at, k));
      return;
    }
    if (std::find(c.bodies.begin(), c.bodies.end(), b) == c.bodies.end())
      r.fail(at, k,
             "'" + b + "' is not one of bodies" +
                 (groupToo    ? " (or ground, or a group)"
                  : groundToo ? " (or ground)"
                              : ""));
  };
  if (const YAML::Node s = n["shapes"]) {
    if (!s.IsMap())
      r.fail(s, key + ".shapes", "expected {body: shape, ...}");
    else
      for (auto it = s.begin(); it != s.end(); ++it) {
        const std::string b = it->first.as<std::string>();
        c.shapes.emplace(b, readShape(r, it->second, key + ".shapes." + b));
        member(b, keyNode(it), key + ".shapes." + b, false);
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
        member(b, keyNode(it), key + ".materials." + b, true);
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
        r.fail(keyNode(it), key + ".contact." + pair,
               "expected default or a pair material_a/material_b");
        continue;
      }
      if (slash != std::string::npos && pair.substr(0, slash) > pair.substr(slash + 1))
        pair = pair.substr(slash + 1) + "/" + pair.substr(0, slash);
      c.laws[pair] = readLaw(r, it->second, key + ".contact." + it->first.as<std::string>());
    }
  }
  readGroups(n, r, key, c);
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
          member(b, ig[i], key + ".ignore[" + std::to_string(i) + "]", true, true);
        c.ignore.emplace_back(pair[0], pair[1]);
      }
  }
  if (const YAML::Node p = n["points_per_pair"]) {
    // (value) => the count, cast only once it is known to be in an int's range
    const double points = r.number(p, key + ".points_per_pair", 4.0);
    if (!(points >= 1))
      r.fail(p, key + ".points_per_pair", "must be >= 1");
    else if (points > 1000)
      r.fail(p, key + ".points_per_pair", "must be at most 1000");
    else
      c.pointsPerPair = static_cast<int>(points);
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
        if (!e["below"]) r.fail(e, k, "missing required key 'below' (m, >= 0)");
        ws.below = nonNegative(r, e["below"], k + ".below", 0.0);
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

}  // namespace yardsim::scene::providers
