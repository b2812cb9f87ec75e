// The `mooring:` key of a `mechanics:` block (docs/scenes.md, docs/lines.md): quasi-static elastic
// catenary lines (forces/lines/catenary_line.hpp) from an anchor to a fairlead on a body, with
// their channels: fairlead and anchor tensions and angles, the horizontal tension, the touchdown
// point and the laid length; or, with `model: lumped`, lumped-mass lines
// (forces/lines/lumped_line_provider.hpp) whose inner nodes are bodies of the system (channels:
// fairlead, anchor and horizontal tensions, fairlead and anchor angles, laid length, touchdown
// point; the nodes' positions are their bodies' channels).
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>

#include "dynamics/kinematics.hpp"
#include "forces/airy_waves.hpp"
#include "forces/current_profile.hpp"
#include "forces/lines/catenary_line.hpp"
#include "forces/lines/lumped_line_provider.hpp"
#include "forces/provider_outputs.hpp"
#include "scene/providers/lumped_line_bodies.hpp"
#include "scene/providers/reader_support.hpp"

namespace yardsim::scene::providers {

namespace {

using forces::CatenaryLine;
using forces::ProviderOutput;
using forces::Stage;
using mechanics::MechanicsSpec;

// (line) => its channels, each from one solve at the committed state (warm-started)
std::vector<ProviderOutput> mooringOutputs(const CatenaryLine& l) {
  auto sol = [&l](const Stage& s) { return l.state(s).solution; };
  return {
      {"fairlead_tension", "N",
       [sol](const Stage& s) {
         const auto c = sol(s);
         return std::hypot(c.hf, c.vf);
       }},
      {"anchor_tension", "N",
       [sol](const Stage& s) {
         const auto c = sol(s);
         return std::hypot(c.ha, c.va);
       }},
      {"horizontal_tension", "N", [sol](const Stage& s) { return sol(s).hf; }},
      // angles below the horizontal of the line's tangent at each end (> 0: the line runs down
      // from the fairlead; at the anchor > 0: it pulls the anchor up)
      {"fairlead_angle", "rad",
       [sol](const Stage& s) {
         const auto c = sol(s);
         return std::atan2(c.vf, c.hf);
       }},
      {"anchor_angle", "rad",
       [sol](const Stage& s) {
         const auto c = sol(s);
         return std::atan2(c.va, c.ha);
       }},
      {"laid_length", "m", [sol](const Stage& s) { return sol(s).laidLength; }},
      // horizontal distance from the anchor to the touchdown point, and that point in the world
      {"touchdown_distance", "m", [sol](const Stage& s) { return sol(s).touchdownX; }},
      {"touchdown_x", "m",
       [&l](const Stage& s) {
         const auto st = l.state(s);
         return dynamics::pointPosition(s.data, l.anchor().body, l.anchor().p_B).x() +
                st.solution.touchdownX * st.horizontal.x();
       }},
      {"touchdown_y", "m",
       [&l](const Stage& s) {
         const auto st = l.state(s);
         return dynamics::pointPosition(s.data, l.anchor().body, l.anchor().p_B).y() +
                st.solution.touchdownX * st.horizontal.y();
       }},
  };
}

// (lumped line) => its channels, from one node-force evaluation at the committed state
std::vector<ProviderOutput> lumpedOutputs(const forces::LumpedLineProvider& l) {
  return {
      {"fairlead_tension", "N", [&l](const Stage& s) { return l.fairleadTension(s); }},
      {"anchor_tension", "N", [&l](const Stage& s) { return l.anchorTension(s); }},
      {"horizontal_tension", "N", [&l](const Stage& s) { return l.horizontalTension(s); }},
      {"laid_length", "m", [&l](const Stage& s) { return l.laidLength(s); }},
      // the catenary's names, units and conventions (mooringOutputs above); the touchdown point
      // is the last node of the run from the anchor on the bed (docs/lines.md)
      {"fairlead_angle", "rad", [&l](const Stage& s) { return l.fairleadAngle(s); }},
      {"anchor_angle", "rad", [&l](const Stage& s) { return l.anchorAngle(s); }},
      {"touchdown_distance", "m", [&l](const Stage& s) { return l.touchdown(s).distance; }},
      {"touchdown_x", "m", [&l](const Stage& s) { return l.touchdown(s).point.x(); }},
      {"touchdown_y", "m", [&l](const Stage& s) { return l.touchdown(s).point.y(); }},
  };
}

// (entry with model: lumped, its ends read) => a LumpedLineProvider and its node bodies: {length,
// EA, EI, mass + diameter, segments, damping | damping_ratio, cdn, cdt, can, cat, water_density,
// gravity, seabed, friction, bed_stiffness, bed_damping}
void readLumped(const YAML::Node& n, const spec::Reader& r, const std::string& key,
                MechanicsSpec::ProviderSpec& out) {
  forces::LumpedLineProperties p;
  p.length = r.number(n["length"], key + ".length", 1.0);
  if (!n["length"]) r.fail(n, key, "missing required key 'length' (unstretched, m)");
  p.ea = r.number(n["EA"], key + ".EA", 1.0);
  if (!n["EA"]) r.fail(n, key, "missing required key 'EA' (N): a lumped line is elastic");
  // (N m^2, bending; 0: none; a negative one is reported at its node and read as 0)
  p.ei = std::max(0.0, nonNegative(r, n["EI"], key + ".EI", 0.0));
  if (n["weight"] || !n["mass"] || !n["diameter"])
    r.fail(n["weight"] ? n["weight"] : n, key,
           "a lumped line needs 'mass' (kg/m in air) and 'diameter' (m), not 'weight'");
  p.massPerLength = r.number(n["mass"], key + ".mass", 1.0);
  p.diameter = r.number(n["diameter"], key + ".diameter", 0.1);
  const double segments = r.number(n["segments"], key + ".segments", 20.0);
  if (!(segments >= 1.0 && segments <= 10000.0 && segments == std::floor(segments)))
    r.fail(n["segments"], key + ".segments", "expected a whole number of segments, 1 to 10000");
  p.segments = static_cast<int>(std::clamp(segments, 1.0, 10000.0));
  // (damping in N s per unit strain rate, or a fraction of a segment's critical damping)
  if (n["damping"] && n["damping_ratio"])
    r.fail(n["damping"], key + ".damping", "give either damping (N s) or damping_ratio");
  p.damping = n["damping"] ? nonNegative(r, n["damping"], key + ".damping", 0.0)
                           : -nonNegative(r, n["damping_ratio"], key + ".damping_ratio", 0.5);
  p.cdn = nonNegative(r, n["cdn"], key + ".cdn", 1.2);
  p.cdt = nonNegative(r, n["cdt"], key + ".cdt", 0.05);
  p.can = nonNegative(r, n["can"], key + ".can", 1.0);
  p.cat = nonNegative(r, n["cat"], key + ".cat", 0.0);
  // (water_density: an override; else the scene's water: density, inSea below)
  const bool ownDensity = static_cast<bool>(n["water_density"]);
  p.waterDensity = nonNegative(r, n["water_density"], key + ".water_density", 1025.0);
  p.gravity = nonNegative(r, n["gravity"], key + ".gravity", 9.81);
  const bool worldAnchor = out.attachments[0].first == "world";
  const double area = 0.25 * M_PI * p.diameter * p.diameter;
  p.seabed = worldAnchor && p.massPerLength > p.waterDensity * area;
  const bool ownSeabed = static_cast<bool>(n["seabed"]);
  if (const YAML::Node s = n["seabed"]) {
    if (!s.IsScalar() || !YAML::convert<bool>::decode(s, p.seabed))
      r.fail(s, key + ".seabed", "expected true or false");
    else if (p.seabed && !worldAnchor)
      r.fail(s, key + ".seabed", "a line on the sea bed needs its anchor in the world");
  }
  p.seabedZ = out.attachments[0].second.z();  // the bed through the anchor
  p.bedStiffness = nonNegative(r, n["bed_stiffness"], key + ".bed_stiffness", 3e6);
  p.bedDamping = nonNegative(r, n["bed_damping"], key + ".bed_damping", 3e5);
  p.bedFriction = nonNegative(r, n["friction"], key + ".friction", 0.0);
  if (n["friction"] && !p.seabed)
    r.fail(n["friction"], key + ".friction", "friction acts on the sea bed: set seabed: true");
  try {
    forces::LumpedLine check(p, key);
  } catch (const std::invalid_argument& e) {
    r.fail(n, key, e.what());
    return;
  }
  // (the scene's environment) => the properties in it: the scene's water density unless the
  // line gives its own, and with it the default sea bed (a sinking line anchored in the world)
  auto inSea = [p, ownDensity, ownSeabed, worldAnchor, area](const MechanicsSpec& env) {
    forces::LumpedLineProperties q = p;
    if (!ownDensity && env.hasWater) q.waterDensity = env.water.density;
    if (!ownSeabed) q.seabed = worldAnchor && q.massPerLength > q.waterDensity * area;
    return q;
  };
  // (full name, ends at q0, the scene's environment) => the inner nodes: point masses on
  // translation joints from the world
  out.bodiesInSea = [inSea](const std::string& name, const std::vector<dynamics::Vector3>& at,
                            const MechanicsSpec& env) {
    const forces::LumpedLineProperties sea = inSea(env);
    const forces::LumpedLine line(sea, name);
    std::vector<MechanicsSpec::Body> bodies;
    for (const auto& node : forces::lumpedLineNodes(line, name, at.at(0), at.at(1)))
      bodies.push_back(lumpedNodeBody(node, sea.diameter));
    return bodies;
  };
  // (full name, the system with its sea, ends) => the provider; the line sees the scene's waves
  // (regular or irregular components) and current, owned with it; none in still water
  out.buildFromSystem = [inSea](const std::string& name, const mechanics::BuiltMechanics& mech,
                                const std::vector<forces::Attachment>& at) {
    struct Owner {
      std::unique_ptr<const forces::AiryWaves> waves;
      std::unique_ptr<const forces::CurrentField> current;
      std::optional<forces::LumpedLine> line;
    };
    auto owner = std::make_shared<Owner>();
    const MechanicsSpec& env = mech.environment;
    const forces::LumpedLineProperties sea = inSea(env);
    if (!env.waves.empty()) {
      forces::WaterProperties water = env.water;  // (as the system's sea: mechanics/system.cpp)
      if (-mech.model.gravity.z() > 0 && !env.hasWater) water.gravity = -mech.model.gravity.z();
      owner->waves = std::make_unique<const forces::AiryWaves>(water, env.waves);
    }
    if (env.current) owner->current = std::make_unique<const forces::CurrentField>(*env.current);
    owner->line.emplace(sea, name, owner->waves.get(), owner->current.get());
    const std::shared_ptr<const forces::LumpedLine> line(owner, &*owner->line);
    return forces::withOutputs<forces::LumpedLineProvider>(
        std::make_unique<forces::LumpedLineProvider>(name, mech.model, at.at(0), at.at(1), line),
        lumpedOutputs);
  };
}

// (entry {anchor, fairlead, model, length, EA, weight | mass + diameter, water_density, seabed,
// friction, and the lumped line's keys}) => a CatenaryLine, or a lumped line with model: lumped
MechanicsSpec::ProviderSpec readMooring(const std::string&, const YAML::Node& n,
                                        const spec::Reader& r, const std::string& key) {
  MechanicsSpec::ProviderSpec out;
  r.keys(n, {"anchor",   "fairlead",      "model",         "length",  "EA",     "weight",
             "mass",     "diameter",      "water_density", "gravity", "seabed", "friction",
             "segments", "damping",       "damping_ratio", "cdn",     "cdt",    "can",
             "cat",      "bed_stiffness", "bed_damping",   "EI"},
         key);
  if (!n.IsMap()) return out;
  out.attachments.push_back(readEnd(r, n, "anchor", key));
  out.attachments.push_back(readEnd(r, n, "fairlead", key));
  if (out.attachments[1].first == "world")
    r.fail(n["fairlead"] ? n["fairlead"] : n, key + ".fairlead", "the fairlead must be on a body");
  // (model: catenary (default) | lumped) => the lumped line's own keys, or the catenary's
  const std::string kind = n["model"] && n["model"].IsScalar() ? n["model"].Scalar() : "catenary";
  if (kind != "catenary" && kind != "lumped")
    r.fail(n["model"], key + ".model", "expected catenary or lumped, got '" + kind + "'");
  if (kind == "lumped") {
    readLumped(n, r, key, out);
    return out;
  }
  for (const char* k : {"segments", "damping", "damping_ratio", "cdn", "cdt", "can", "cat",
                        "bed_stiffness", "bed_damping", "EI"})
    if (n[k]) r.fail(n[k], key + "." + k, std::string("'") + k + "' is a key of model: lumped");
  forces::CatenaryParameters p;
  p.length = r.number(n["length"], key + ".length", 1.0);
  if (!n["length"]) r.fail(n, key, "missing required key 'length' (unstretched, m)");
  p.ea = n["EA"] ? r.number(n["EA"], key + ".EA", 1.0) : std::numeric_limits<double>::infinity();
  // (weight in water, N/m) or (mass in air kg/m, volume-equivalent diameter m: w = (m - rho A) g)
  if (n["weight"] && (n["mass"] || n["diameter"]))
    r.fail(n["weight"], key + ".weight", "give either weight (N/m in water) or mass and diameter");
  if (n["weight"]) {
    p.weight = r.number(n["weight"], key + ".weight", 1.0);
  } else if (n["mass"] && n["diameter"]) {
    const double m = nonNegative(r, n["mass"], key + ".mass", 1.0);
    const double d = nonNegative(r, n["diameter"], key + ".diameter", 0.0);
    const double rho = nonNegative(r, n["water_density"], key + ".water_density", 1025.0);
    const double g = nonNegative(r, n["gravity"], key + ".gravity", 9.81);
    p.weight = (m - rho * M_PI / 4.0 * d * d) * g;
  } else {
    r.fail(n, key, "missing 'weight' (N/m in water) or 'mass' (kg/m) and 'diameter' (m)");
    p.weight = 1.0;
  }
  const bool worldAnchor = out.attachments[0].first == "world";
  p.seabed = worldAnchor && p.weight > 0;  // (default) a sinking line from a ground anchor
  if (const YAML::Node s = n["seabed"]) {
    if (!s.IsScalar() || !YAML::convert<bool>::decode(s, p.seabed))
      r.fail(s, key + ".seabed", "expected true or false");
    else if (p.seabed && !worldAnchor)
      r.fail(s, key + ".seabed", "a line on the sea bed needs its anchor in the world");
  }
  p.friction = nonNegative(r, n["friction"], key + ".friction", 0.0);
  if (n["friction"] && !p.seabed)
    r.fail(n["friction"], key + ".friction", "friction acts on the sea bed: set seabed: true");
  if (const std::string e = forces::catenaryParameterError(p); !e.empty()) r.fail(n, key, e);
  // (name, the system's model, the attachments placed) => the provider with its channels
  out.build = [p](const std::string& name, const dynamics::Model& model,
                  const std::vector<forces::Attachment>& at) {
    return forces::withOutputs<CatenaryLine>(
        std::make_unique<CatenaryLine>(name, model, at.at(0), at.at(1), p), mooringOutputs);
  };
  return out;
}

}  // namespace

YARDSIM_REGISTER_PROVIDER(mooring,
                          ProviderReader{
                              .key = "mooring",
                              .summary = "name: {anchor: [x, y, z] | {body, point}, fairlead: "
                                         "{body, point}, length, EA, weight | mass + diameter, "
                                         "seabed, friction, model: catenary | lumped, segments, "
                                         "damping_ratio, cdn, cdt, can, cat, EI}",
                              .read = readMooring});

}  // namespace yardsim::scene::providers
