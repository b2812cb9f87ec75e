// `ropes:` entries with `model: lumped`: a crane rope (hoist wire, sling) with mass, the
// lumped-mass line of the mooring lines between the two points of its path
// (forces/lines/lumped_line_provider.hpp), or over the middle one of three, a sheave
// (forces/lines/lumped_rope_over_sheave.hpp); in still air: its weight with the air's buoyancy,
// no drag, no added mass, no sea bed. Channels: the force on each end's body, the largest segment
// tension, the stretched length, over a sheave the tension there; the inner nodes are bodies
// (their positions are their channels, their spheres are drawn in the replay). Between two
// points the rope has a winch (a wire actor pays it out or hauls it in: every segment's
// unstretched length follows L(t) / n), with the unstretched length as a channel.
#include "scene/providers/lumped_rope_reader.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>

#include "forces/lines/lumped_line_provider.hpp"
#include "forces/lines/lumped_rope_over_sheave.hpp"
#include "forces/provider_outputs.hpp"
#include "scene/providers/lumped_line_bodies.hpp"
#include "scene/providers/reader_support.hpp"

namespace yardsim::scene::providers {

namespace {

using forces::LumpedLineProvider;
using forces::ProviderOutput;
using forces::Stage;

constexpr double kAirDensity = 1.225;  // kg/m^3: the fluid a crane rope hangs in

// (rope, stage) => its nodes, node forces and segment tensions there, in a scratch of its own
// (the channels are read at recorded states, not in the integrator's stages)
LumpedLineProvider::Scratch evaluated(const LumpedLineProvider& l, const Stage& s) {
  const auto made = l.makeScratch();
  auto& w = static_cast<LumpedLineProvider::Scratch&>(*made);
  l.gather(s, w);
  l.line().nodeForces(w.r, w.v, s.t, w.f, w.tension);
  return std::move(w);
}

// (a span evaluated) => the length of its chords, m
double chordLength(const LumpedLineProvider::Scratch& w) {
  double len = 0.0;
  for (Eigen::Index i = 1; i < w.r.cols(); ++i) len += (w.r.col(i) - w.r.col(i - 1)).norm();
  return len;
}

// (rope) => its channels: the force on the first and last end's body (N: the end segment's
// tension with the half segment's weight), the largest segment tension (N), the length (m), the
// unstretched length its winch has paid out to (m)
std::vector<ProviderOutput> lumpedRopeOutputs(const LumpedLineProvider& l) {
  return {
      {"unstretched_length", "m",
       [&l](const Stage& s) {
         const forces::Winch* w = l.line().winch();
         return w ? w->length(s.t) : l.line().properties().length;
       }},
      {"first_tension", "N", [&l](const Stage& s) { return evaluated(l, s).f.col(0).norm(); }},
      {"last_tension", "N",
       [&l](const Stage& s) {
         const auto w = evaluated(l, s);
         return w.f.col(w.f.cols() - 1).norm();
       }},
      {"max_tension", "N", [&l](const Stage& s) { return evaluated(l, s).tension.maxCoeff(); }},
      {"length", "m", [&l](const Stage& s) { return chordLength(evaluated(l, s)); }},
  };
}

// (rope's properties, the system's model) => its properties under the model's gravity (the
// root's, which an included fragment's may not state); it must point down -z
forces::LumpedLineProperties underGravity(forces::LumpedLineProperties p,
                                          const dynamics::Model& model, const std::string& name) {
  if (model.gravity.head<2>().norm() > 0.0 || !(model.gravity.z() < 0.0))
    throw std::invalid_argument("rope '" + name + "': a lumped rope needs gravity down -z");
  p.gravity = -model.gravity.z();
  return p;
}

// (the whole rope's properties, segments, the length per segment) => one span's
forces::LumpedLineProperties spanOf(forces::LumpedLineProperties p, int segments) {
  p.length = p.length / p.segments * segments;
  p.segments = segments;
  return p;
}

// (rope over a sheave) => its channels: the force on the first end's body (span A's first node)
// and on the last end's (span B's last), the tension over the sheave, the largest tension, the
// length
std::vector<ProviderOutput> overSheaveOutputs(const forces::LumpedRopeOverSheave& l) {
  return {
      {"first_tension", "N",
       [&l](const Stage& s) { return evaluated(l.spanA(), s).f.col(0).norm(); }},
      {"last_tension", "N",
       [&l](const Stage& s) {
         const auto w = evaluated(l.spanB(), s);
         return w.f.col(w.f.cols() - 1).norm();
       }},
      {"sheave_tension", "N", [&l](const Stage& s) { return l.sheaveTension(s); }},
      {"max_tension", "N",
       [&l](const Stage& s) {
         return std::max({evaluated(l.spanA(), s).tension.maxCoeff(),
                          evaluated(l.spanB(), s).tension.maxCoeff(), l.sheaveTension(s)});
       }},
      {"length", "m",
       [&l](const Stage& s) {
         Stage alone = s;
         alone.scratch = nullptr;
         return chordLength(evaluated(l.spanA(), s)) + chordLength(evaluated(l.spanB(), s)) +
                l.overSheave().length(alone);
       }},
  };
}

// (the rope's properties) => its bodies over a sheave: (full name, first end, sheave point and
// last end at q0) => span A's inner nodes (at rest between the first end and p), p and q (half a
// segment from the sheave point toward each end, stretched by the rope's mean strain along the
// straight path), span B's inner nodes
mechanics::MechanicsSpec::ProviderBodies overSheaveBodies(const forces::LumpedLineProperties& p) {
  return [p](const std::string& name, const std::vector<dynamics::Vector3>& at) {
    const dynamics::Vector3 &a = at.at(0), &s = at.at(1), &b = at.at(2);
    const int na = forces::firstSpanSegments(p.segments, a, s, b), nb = p.segments - 1 - na;
    const double l = p.length / p.segments;
    const double strain = std::max(0.0, ((a - s).norm() + (b - s).norm()) / p.length - 1.0);
    auto toward = [&](const dynamics::Vector3& end) {
      const dynamics::Vector3 d = end - s;
      const dynamics::Vector3 u = d.norm() > 0.0 ? dynamics::Vector3(d.normalized())
                                                 : dynamics::Vector3(-dynamics::Vector3::UnitZ());
      return dynamics::Vector3(s + 0.5 * l * (1.0 + strain) * u);
    };
    const dynamics::Vector3 pp = toward(a), pq = toward(b);
    const forces::LumpedLine spanA(spanOf(p, na), name + ".a"), spanB(spanOf(p, nb), name + ".b");
    std::vector<mechanics::MechanicsSpec::Body> bodies;
    for (const auto& node : forces::lumpedLineNodes(spanA, name + ".a", a, pp))
      bodies.push_back(lumpedNodeBody(node, p.diameter));
    const double mass = p.massPerLength * l;  // (half of a span's end segment, half the sheave's)
    bodies.push_back(
        lumpedNodeBody({forces::sheaveNodeName(name, true, na), mass, pp}, p.diameter));
    bodies.push_back(
        lumpedNodeBody({forces::sheaveNodeName(name, false, na), mass, pq}, p.diameter));
    for (const auto& node : forces::lumpedLineNodes(spanB, name + ".b", pq, b))
      bodies.push_back(lumpedNodeBody(node, p.diameter));
    return bodies;
  };
}

// (the rope's properties) => its provider over a sheave: span A's segments found from its node
// bodies in the model, the sheave segment's damping the lumped segments' c / l
mechanics::MechanicsSpec::ProviderBuild overSheaveBuild(const forces::LumpedLineProperties& p) {
  return [p](const std::string& name, const dynamics::Model& model,
             const std::vector<forces::Attachment>& at) {
    const forces::LumpedLineProperties q = underGravity(p, model, name);
    int na = 1;  // (nodes 1 .. n_A of span A are bodies, the last one p)
    while (na + 2 < q.segments && model.bodyIndex(forces::sheaveNodeName(name, true, na + 1)) >= 0)
      ++na;
    const int nb = q.segments - 1 - na;
    auto spanA = std::make_shared<const forces::LumpedLine>(spanOf(q, na), name + ".a");
    auto spanB = std::make_shared<const forces::LumpedLine>(spanOf(q, nb), name + ".b");
    const double damping = spanA->dampingCoefficient() / spanA->segmentLength();
    return forces::withOutputs<forces::LumpedRopeOverSheave>(
        std::make_unique<forces::LumpedRopeOverSheave>(name, model, at.at(0), at.at(1), at.at(2),
                                                       std::move(spanA), std::move(spanB), damping),
        overSheaveOutputs);
  };
}

// (a lumped rope's entry, its path read, the block's gravity) => its provider spec, or nullopt
// after a problem reported at its node
std::optional<mechanics::MechanicsSpec::ProviderSpec> readLumped(
    const spec::Reader& r, const YAML::Node& n, const std::string& key,
    const std::vector<mechanics::MechanicsSpec::Point>& path, const dynamics::Vector3& gravity) {
  bool refused = false;
  auto fail = [&](const YAML::Node& at, const std::string& k, const std::string& what) {
    refused = true;
    r.fail(at, k, what);
  };
  forces::LumpedLineProperties p;
  // (what a lumped rope does not do yet) => refused at its node
  if (path.size() > 3)
    fail(n["path"], key + ".path",
         "a lumped rope runs between two points or over one sheave (first end, sheave, last end); "
         "for more sheaves use the massless rope");
  if (n["parts"] && !(n["parts"].IsScalar() && n["parts"].Scalar() == "1"))
    fail(n["parts"], key + ".parts",
         "a lumped rope is one part (reeve multi-part hoists massless)");
  if (n["mbl"])
    fail(n["mbl"], key + ".mbl", "'mbl' is a key of the massless rope, not of model: lumped");
  if (n["min_length"] && path.size() == 3)
    fail(n["min_length"], key + ".min_length",
         "a lumped rope over a sheave has no winch, so no minimum length");
  if (gravity.head<2>().norm() > 0.0 || !(gravity.z() < 0.0))
    fail(n["model"], key + ".model",
         "a lumped rope hangs under the block's gravity, which must point down -z");
  // (EA, L0, mass per length, diameter: required and > 0)
  auto positive = [&](const char* k, const char* what) {
    if (!r.required(n, k, key, what)) {
      refused = true;
      return 1.0;
    }
    const double v = r.number(n[k], key + "." + k, 1.0);
    if (!(v > 0.0 && std::isfinite(v))) fail(n[k], key + "." + k, std::string(k) + " must be > 0");
    return v;
  };
  p.ea = positive("EA", "N, the axial stiffness");
  p.length = positive("L0", "m, the unstretched length");
  p.massPerLength = positive("mass_per_length", "kg/m, the rope's mass per unstretched length");
  p.diameter = positive("diameter", "m, the rope's: the air's buoyancy and the replay's nodes");
  // (N m^2, bending; 0: none; a negative one is reported at its node and read as 0)
  p.ei = std::max(0.0, nonNegative(r, n["EI"], key + ".EI", 0.0));
  const double segments = r.number(n["segments"], key + ".segments", 10.0);
  if (!(segments >= 1.0 && segments <= 10000.0 && segments == std::floor(segments)))
    fail(n["segments"], key + ".segments", "expected a whole number of segments, 1 to 10000");
  p.segments = static_cast<int>(std::clamp(std::floor(segments), 1.0, 10000.0));
  if (path.size() == 3 && p.segments < 3)
    fail(n["segments"] ? n["segments"] : n, key + ".segments",
         "a lumped rope over a sheave needs at least 3 segments (a span on each side and one over "
         "the sheave)");
  // (damping N s/m on the rope's elongation rate, as the massless rope's: per segment c L0 N s
  // per unit strain rate; or a fraction of a segment's critical damping, default 0.5)
  if (n["damping"] && n["damping_ratio"])
    fail(n["damping"], key + ".damping", "give either damping (N s/m) or damping_ratio");
  p.damping = n["damping"] ? nonNegative(r, n["damping"], key + ".damping", 0.0) * p.length
                           : -nonNegative(r, n["damping_ratio"], key + ".damping_ratio", 0.5);
  p.cdn = p.cdt = p.can = p.cat = 0.0;
  p.waterDensity = kAirDensity;
  p.gravity = gravity.z() < 0.0 ? -gravity.z() : 9.81;
  p.seabed = false;
  // (m: the shortest unstretched length its winch hauls in to, as the massless rope's)
  const double minLength = r.number(n["min_length"], key + ".min_length", 0.01);
  if (!(minLength > 0.0 && minLength <= p.length))
    fail(n["min_length"] ? n["min_length"] : n, key + ".min_length",
         "min_length must be > 0 and <= L0 (m)");
  if (refused) return std::nullopt;
  try {
    forces::LumpedLine check(p, key);
  } catch (const std::invalid_argument& e) {
    r.fail(n, key, e.what());
    return std::nullopt;
  }
  mechanics::MechanicsSpec::ProviderSpec out;
  out.attachments = path;
  if (path.size() == 3) {
    out.bodies = overSheaveBodies(p);
    out.build = overSheaveBuild(p);
    return out;
  }
  out.bodies = lumpedLineBodies(p);
  out.winch = true;
  // (full name, the system's model, the ends placed) => the provider with its winch at L0, its
  // weight under the system's gravity (the root's, which an included fragment's may not state)
  out.build = [p, minLength](const std::string& name, const dynamics::Model& model,
                             const std::vector<forces::Attachment>& at) {
    auto winch = std::make_shared<forces::Winch>(p.length, minLength);
    auto line = std::make_shared<const forces::LumpedLine>(underGravity(p, model, name), name,
                                                           nullptr, nullptr, winch);
    return forces::withOutputs<LumpedLineProvider>(
        std::make_unique<LumpedLineProvider>(name, model, at.at(0), at.at(1), std::move(line),
                                             std::move(winch)),
        lumpedRopeOutputs);
  };
  return out;
}

}  // namespace

bool readLumpedRope(const spec::Reader& r, const YAML::Node& n, const std::string& key,
                    mechanics::MechanicsSpec& spec) {
  const YAML::Node model = n.IsMap() ? n["model"] : YAML::Node();
  if (!model) return false;
  if (!model.IsScalar() || model.Scalar() != "lumped") {
    if (!model.IsScalar() || model.Scalar() != "massless")
      r.fail(model, key + ".model",
             "expected massless (the default) or lumped, got '" +
                 (model.IsScalar() ? model.Scalar() : std::string("a collection")) + "'");
    return false;
  }
  static const std::vector<std::string> keys{
      "model",   "path",          "EA",    "L0",  "mass_per_length", "diameter", "segments",
      "damping", "damping_ratio", "parts", "mbl", "min_length",      "EI"};
  if (!r.keys(n, keys, key)) return true;
  // (path: first end, [sheave,] last end) => points; their bodies are checked when the fragments
  // are merged
  const YAML::Node at = n["path"];
  if (!at || !at.IsSequence() || at.size() < 2) {
    r.fail(at ? at : n, key + ".path",
           "expected a list of 2 or 3 points {body, point: [x, y, z]} (first end, [sheave,] last "
           "end)");
    return true;
  }
  std::vector<mechanics::MechanicsSpec::Point> path;
  for (std::size_t i = 0; i < at.size(); ++i)
    path.push_back(readPoint(r, at[i], key + ".path[" + std::to_string(i) + "]"));
  if (auto ps = readLumped(r, n, key, path, spec.gravity)) {
    ps->kind = "ropes";
    ps->name = key;
    spec.providers.push_back(std::move(*ps));
  }
  return true;
}

}  // namespace yardsim::scene::providers
