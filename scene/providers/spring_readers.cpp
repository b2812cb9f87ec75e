// The `springs:` and `joint_springs:` keys of a `mechanics:` block (docs/scenes.md): translational
// spring-dampers between two points (forces/spring_damper.hpp) and spring-dampers on one
// coordinate of a joint (forces/rotational_spring_damper.hpp), with their channels.
#include <cmath>
#include <limits>

#include "forces/provider_outputs.hpp"
#include "forces/rotational_spring_damper.hpp"
#include "forces/spring_damper.hpp"
#include "scene/providers/reader_support.hpp"

namespace yardsim::scene::providers {

namespace {

using mechanics::MechanicsSpec;

// (entry {between, k | table, c, free_length, preload, stops}) => a SpringDamper with the
// channels force (N, > 0 pulls the ends together) and length (m)
MechanicsSpec::ProviderSpec readSpring(const std::string&, const YAML::Node& n,
                                       const spec::Reader& r, const std::string& key) {
  MechanicsSpec::ProviderSpec out;
  r.keys(n, {"between", "k", "table", "c", "free_length", "preload", "stops"}, key);
  if (!n.IsMap()) return out;
  const YAML::Node ends = n["between"];
  if (!ends || !ends.IsSequence() || ends.size() != 2) {
    r.fail(ends ? ends : n, key + ".between", "expected two points [{body, point}, {body, point}]");
  } else {
    for (std::size_t i = 0; i < 2; ++i)
      out.attachments.push_back(readPoint(r, ends[i], key + ".between[" + std::to_string(i) + "]"));
  }
  forces::SpringDamperProperties p;
  if (const auto curve = readCurve(r, n, key, "N")) p.curve = *curve;
  p.freeLength = nonNegative(r, n["free_length"], key + ".free_length", 0.0);
  if (!n["free_length"]) r.fail(n, key, "missing required key 'free_length' (m)");
  p.damping = nonNegative(r, n["c"], key + ".c", 0.0);
  p.preload = r.number(n["preload"], key + ".preload", 0.0);
  if (const YAML::Node s = n["stops"]) {  // (stops {min_length, max_length, k}) => the stops
    r.keys(s, {"min_length", "max_length", "k"}, key + ".stops");
    p.minLength = nonNegative(r, s["min_length"], key + ".stops.min_length", 0.0);
    p.maxLength = nonNegative(r, s["max_length"], key + ".stops.max_length",
                              std::numeric_limits<double>::infinity());
    p.stopStiffness = nonNegative(r, s["k"], key + ".stops.k", 0.0, true);
    if (p.minLength > p.maxLength)
      r.fail(s, key + ".stops", "min_length must not exceed max_length");
  }
  // (name, the system's model, the attachments placed) => the provider with its channels
  out.build = [p](const std::string& name, const dynamics::Model& model,
                  const std::vector<forces::Attachment>& at) {
    auto spring = std::make_unique<forces::SpringDamper>(name, model, at.at(0), at.at(1), p);
    return forces::withOutputs<forces::SpringDamper>(
        std::move(spring), [](const forces::SpringDamper& s) {
          return std::vector<forces::ProviderOutput>{
              {"force", "N", [&s](const forces::Stage& st) { return s.state(st).force; }},
              {"length", "m", [&s](const forces::Stage& st) { return s.state(st).length; }}};
        });
  };
  return out;
}

// (entry {body, coordinate, k | table, c, neutral | neutral_deg, preload}) => a spring-damper on
// the joint of `body` (to its parent), with the channels force (N m or N, the generalized force
// it applies) and deflection (rad or m, q - q0)
MechanicsSpec::ProviderSpec readJointSpring(const std::string&, const YAML::Node& n,
                                            const spec::Reader& r, const std::string& key) {
  MechanicsSpec::ProviderSpec out;
  r.keys(n, {"body", "coordinate", "k", "table", "c", "neutral", "neutral_deg", "preload"}, key);
  if (!n.IsMap()) return out;
  out.attachments.push_back({bodyName(r, n, "body", key + ".body"), dynamics::Vector3::Zero()});
  if (out.attachments[0].first == "world")
    r.fail(n["body"] ? n["body"] : n, key + ".body",
           "a joint spring acts on a body's joint, not on the world");
  forces::JointSpringProperties p;
  if (const auto curve = readCurve(r, n, key, "N m or N")) p.curve = *curve;
  p.damping = nonNegative(r, n["c"], key + ".c", 0.0);
  p.preload = r.number(n["preload"], key + ".preload", 0.0);
  if (n["neutral"] && n["neutral_deg"])
    r.fail(n["neutral_deg"], key + ".neutral_deg", "give either neutral or neutral_deg");
  p.neutral = n["neutral_deg"] ? r.number(n["neutral_deg"], key + ".neutral_deg", 0.0) * spec::kDeg
                               : r.number(n["neutral"], key + ".neutral", 0.0);
  const double c = nonNegative(r, n["coordinate"], key + ".coordinate", 0.0);
  // (value) => the coordinate's index, cast only once it is a whole number in an int's range
  const bool whole = c == std::floor(c) && c <= 1e6;
  if (!whole) r.fail(n["coordinate"], key + ".coordinate", "expected a whole number up to 1000000");
  const int coordinate = whole ? static_cast<int>(c) : 0;
  // (name, the system's model, the attachments placed) => the provider with its channels
  out.build = [p, coordinate](const std::string& name, const dynamics::Model& model,
                              const std::vector<forces::Attachment>& at) {
    const int body = at.at(0).body;
    auto spring =
        std::make_unique<forces::RotationalSpringDamper>(name, model, body, coordinate, p);
    const bool linear = model.joints[body].type == dynamics::JointType::Prismatic;
    return forces::withOutputs<forces::RotationalSpringDamper>(
        std::move(spring), [linear](const forces::RotationalSpringDamper& s) {
          return std::vector<forces::ProviderOutput>{
              {"force", linear ? "N" : "N m",
               [&s](const forces::Stage& st) { return s.generalizedForce(st); }},
              {"deflection", linear ? "m" : "rad", [&s](const forces::Stage& st) {
                 return st.q[s.configurationIndex()] - s.properties().neutral;
               }}};
        });
  };
  return out;
}

}  // namespace

YARDSIM_REGISTER_PROVIDER(springs,
                          ProviderReader{
                              .key = "springs",
                              .summary = "name: {between: [{body, point}, {body, point}], k | "
                                         "table, c, free_length, preload, stops}",
                              .read = readSpring});

YARDSIM_REGISTER_PROVIDER(jointSprings,
                          ProviderReader{
                              .key = "joint_springs",
                              .summary = "name: {body, coordinate, k | table, c, neutral, preload}",
                              .read = readJointSpring});

}  // namespace yardsim::scene::providers
