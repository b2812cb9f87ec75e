// The `mooring:` key of a `mechanics:` block (docs/scenes.md): quasi-static elastic catenary lines
// (forces/lines/catenary_line.hpp) from an anchor to a fairlead on a body, with their channels:
// fairlead and anchor tensions and angles, the horizontal tension, the touchdown point and the
// laid length.
#include <cmath>
#include <limits>

#include "dynamics/kinematics.hpp"
#include "forces/lines/catenary_line.hpp"
#include "forces/provider_outputs.hpp"
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

// (entry {anchor, fairlead, length, EA, weight | mass + diameter, water_density, seabed,
// friction}) => a CatenaryLine
MechanicsSpec::ProviderSpec readMooring(const std::string&, const YAML::Node& n,
                                        const spec::Reader& r, const std::string& key) {
  MechanicsSpec::ProviderSpec out;
  r.keys(n,
         {"anchor", "fairlead", "length", "EA", "weight", "mass", "diameter", "water_density",
          "gravity", "seabed", "friction"},
         key);
  if (!n.IsMap()) return out;
  out.attachments.push_back(readEnd(r, n, "anchor", key));
  out.attachments.push_back(readEnd(r, n, "fairlead", key));
  if (out.attachments[1].first == "world")
    r.fail(n["fairlead"] ? n["fairlead"] : n, key + ".fairlead", "the fairlead must be on a body");
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
                                         "seabed, friction}",
                              .read = readMooring});

}  // namespace yardsim::scene::providers
