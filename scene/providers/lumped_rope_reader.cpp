// `ropes:` entries with `model: lumped`: a crane rope (hoist wire, sling) with mass, the
// lumped-mass line of the mooring lines between the two points of its path, in still air: its
// weight with the air's buoyancy, no drag, no added mass, no sea bed. Channels: the force on each
// end's body, the largest segment tension, the stretched length; the inner nodes are bodies
// `<rope>.node<i>` (their positions are their channels, their spheres are drawn in the replay).
#include "scene/providers/lumped_rope_reader.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "forces/lines/lumped_line_provider.hpp"
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

// (rope) => its channels: the force on the first and last end's body (N: the end segment's
// tension with the half segment's weight), the largest segment tension (N), the length (m)
std::vector<ProviderOutput> lumpedRopeOutputs(const LumpedLineProvider& l) {
  return {
      {"first_tension", "N", [&l](const Stage& s) { return evaluated(l, s).f.col(0).norm(); }},
      {"last_tension", "N",
       [&l](const Stage& s) {
         const auto w = evaluated(l, s);
         return w.f.col(w.f.cols() - 1).norm();
       }},
      {"max_tension", "N", [&l](const Stage& s) { return evaluated(l, s).tension.maxCoeff(); }},
      {"length", "m",
       [&l](const Stage& s) {
         const auto w = evaluated(l, s);
         double len = 0.0;
         for (Eigen::Index i = 1; i < w.r.cols(); ++i) len += (w.r.col(i) - w.r.col(i - 1)).norm();
         return len;
       }},
  };
}

}  // namespace

const std::vector<std::string>& lumpedRopeKeys() {
  static const std::vector<std::string> keys{
      "model",   "path",          "EA",    "L0",  "mass_per_length", "diameter", "segments",
      "damping", "damping_ratio", "parts", "mbl", "min_length"};
  return keys;
}

std::optional<mechanics::MechanicsSpec::ProviderSpec> readLumpedRope(
    const spec::Reader& r, const YAML::Node& n, const std::string& key,
    const std::vector<mechanics::MechanicsSpec::Point>& path, const dynamics::Vector3& gravity) {
  bool refused = false;
  auto fail = [&](const YAML::Node& at, const std::string& k, const std::string& what) {
    refused = true;
    r.fail(at, k, what);
  };
  forces::LumpedLineProperties p;
  // (what a lumped rope does not do yet) => refused at its node
  if (path.size() > 2)
    fail(n["path"], key + ".path",
         "a lumped rope runs between two points: sheaves in its path are not supported (use "
         "the massless rope, or one lumped rope per free span)");
  if (n["parts"] && !(n["parts"].IsScalar() && n["parts"].Scalar() == "1"))
    fail(n["parts"], key + ".parts",
         "a lumped rope is one part (reeve multi-part hoists massless)");
  for (const char* k : {"mbl", "min_length"})
    if (n[k])
      fail(n[k], key + "." + k,
           std::string("'") + k + "' is a key of the massless rope, not of model: lumped");
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
  const double segments = r.number(n["segments"], key + ".segments", 10.0);
  if (!(segments >= 1.0 && segments <= 10000.0 && segments == std::floor(segments)))
    fail(n["segments"], key + ".segments", "expected a whole number of segments, 1 to 10000");
  p.segments = static_cast<int>(std::clamp(std::floor(segments), 1.0, 10000.0));
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
  if (refused) return std::nullopt;
  try {
    forces::LumpedLine check(p, key);
  } catch (const std::invalid_argument& e) {
    r.fail(n, key, e.what());
    return std::nullopt;
  }
  mechanics::MechanicsSpec::ProviderSpec out;
  out.attachments = {path.at(0), path.at(1)};
  out.bodies = lumpedLineBodies(p);
  // (full name, the system's model, the ends placed) => the provider, its weight under the
  // system's gravity (the root's, which an included fragment's may not state)
  out.build = [p](const std::string& name, const dynamics::Model& model,
                  const std::vector<forces::Attachment>& at) {
    forces::LumpedLineProperties q = p;
    if (model.gravity.head<2>().norm() > 0.0 || !(model.gravity.z() < 0.0))
      throw std::invalid_argument("rope '" + name + "': a lumped rope needs gravity down -z");
    q.gravity = -model.gravity.z();
    auto line = std::make_shared<const forces::LumpedLine>(q, name);
    return forces::withOutputs<LumpedLineProvider>(
        std::make_unique<LumpedLineProvider>(name, model, at.at(0), at.at(1), std::move(line)),
        lumpedRopeOutputs);
  };
  return out;
}

}  // namespace yardsim::scene::providers
