#include "scene/floating_reader.hpp"

#include <filesystem>

#include "scene/mechanics_reader.hpp"
#include "forces/geometry/mesh_io.hpp"
#include "scene/spec_reader.hpp"

namespace yardsim::scene {

using mechanics::MechanicsSpec;
using models::Params;
using models::didYouMean;
namespace {

using dynamics::Vector3;
using spec::kDeg;
using spec::Reader;

// (node, key, `name_deg` or `name`) => an angle in rad (0 when neither is there)
double angle(const Reader& r, const YAML::Node& n, const std::string& key, const std::string& name) {
  if (n[name + "_deg"]) return kDeg * r.number(n[name + "_deg"], key + "." + name + "_deg", 0.0);
  return r.number(n[name], key + "." + name, 0.0);
}

// (body name) => reported when unknown (globally resolved later in a scene's fragments)
void body(const Reader& r, const YAML::Node& n, const std::string& key, const std::set<std::string>& bodies,
          std::string& out) {
  if (!n["body"] || !n["body"].IsScalar()) {
    r.fail(n, key, "missing required key 'body' (the body it acts on)");
    return;
  }
  out = n["body"].Scalar();
  if (out == "world") {
    r.fail(n["body"], key + ".body", "it acts on a moving body, not the world");
  } else if (!bodies.count(out)) {
    std::vector<std::string> known(bodies.begin(), bodies.end());
    const std::string hint = didYouMean(out, known);
    r.fail(n["body"], key + ".body", "unknown body '" + out + "'" + (hint.empty() ? "" : " (" + hint + ")"));
  }
}

void water(const Reader& r, const YAML::Node& n, MechanicsSpec& spec) {
  if (!r.keys(n, {"density", "level", "depth", "waves", "wave_ramp", "wave_start", "current"}, "")) return;
  spec.hasWater = true;
  forces::WaterProperties& w = spec.water;
  w.density = r.number(n["density"], "density", w.density);
  w.level = r.number(n["level"], "level", w.level);
  w.depth = r.number(n["depth"], "depth", w.depth);
  w.ramp = r.number(n["wave_ramp"], "wave_ramp", 0.0);
  w.start = r.number(n["wave_start"], "wave_start", 0.0);
  w.gravity = -spec.gravity.z() > 0 ? -spec.gravity.z() : 9.81;
  if (n["density"] && !(w.density > 0)) r.fail(n["density"], "density", "the water density must be > 0 kg/m^3");
  if (n["depth"] && !(w.depth > 0)) r.fail(n["depth"], "depth", "the water depth must be > 0 m (omit it for deep water)");
  if (n["wave_ramp"] && !(w.ramp >= 0)) r.fail(n["wave_ramp"], "wave_ramp", "the ramp time must be >= 0 s");
  if (const YAML::Node ws = n["waves"]) {
    if (!ws.IsSequence()) {
      r.fail(ws, "waves", "expected a list of regular waves [{height, period, direction_deg, phase_deg}, ...]");
    } else {
      for (std::size_t i = 0; i < ws.size(); ++i) {
        const std::string k = "waves[" + std::to_string(i) + "]";
        if (!r.keys(ws[i], {"height", "period", "direction", "direction_deg", "phase", "phase_deg"}, k)) continue;
        forces::WaveComponent c;
        c.height = r.number(ws[i]["height"], k + ".height", 0.0, true);
        c.period = r.number(ws[i]["period"], k + ".period", 0.0, true);
        c.direction = angle(r, ws[i], k, "direction");
        c.phase = angle(r, ws[i], k, "phase");
        try {  // (the wave on this water) => positive, not breaking
          forces::AiryWaves(w, {c});
          spec.waves.push_back(c);
        } catch (const std::invalid_argument& e) {
          const std::string what = e.what();
          r.fail(ws[i], k, what.substr(what.find(": ") + 2));
        }
      }
    }
  }
  if (const YAML::Node c = n["current"]) {
    if (!r.keys(c, {"speed", "direction", "direction_deg", "profile"}, "current")) return;
    forces::CurrentProperties cp;
    cp.speed = r.number(c["speed"], "current.speed", 0.0, true);
    cp.direction = angle(r, c, "current", "direction");
    cp.level = w.level;
    if (const YAML::Node pr = c["profile"]) {
      if (!pr.IsSequence()) r.fail(pr, "current.profile", "expected a list of [z, factor] pairs (z from the still-water level, m)");
      else
        for (std::size_t i = 0; i < pr.size(); ++i) {
          const auto v = r.numbers(pr[i], "current.profile[" + std::to_string(i) + "]", 2);
          cp.profile.emplace_back(v[0], v[1]);
        }
    }
    try {
      forces::CurrentField check(cp);
      spec.current = cp;
    } catch (const std::invalid_argument& e) {
      r.fail(c, "current", e.what());
    }
  }
}

void wind(const Reader& r, const YAML::Node& n, MechanicsSpec& spec) {
  if (!r.keys(n, {"speed", "direction", "direction_deg", "reference_height", "profile", "exponent",
                  "averaging_time", "air_density", "min_height"}, ""))
    return;
  forces::WindProperties w;
  w.speed = r.number(n["speed"], "speed", 0.0, true);
  w.direction = angle(r, n, "", "direction");
  w.referenceHeight = r.number(n["reference_height"], "reference_height", w.referenceHeight);
  w.exponent = r.number(n["exponent"], "exponent", w.exponent);
  w.averagingTime = r.number(n["averaging_time"], "averaging_time", w.averagingTime);
  w.density = r.number(n["air_density"], "air_density", w.density);
  w.minHeight = r.number(n["min_height"], "min_height", w.minHeight);
  w.level = spec.water.level;
  if (const YAML::Node pr = n["profile"]) {
    try {
      w.profile = forces::windProfileKind(pr.IsScalar() ? pr.Scalar() : "");
    } catch (const std::invalid_argument& e) {
      r.fail(pr, "profile", std::string(e.what()) + " " + didYouMean(pr.IsScalar() ? pr.Scalar() : "", {"uniform", "power_law", "npd"}));
      return;
    }
  }
  try {
    forces::WindField check(w);
    spec.wind = w;
  } catch (const std::invalid_argument& e) {
    r.fail(n, "", e.what());
  }
}

// (mesh path relative to the YAML file, placement, scale) => the hull in the body frame
void hulls(const Reader& r, const YAML::Node& n, const std::string& file, const std::set<std::string>& bodies,
           MechanicsSpec& spec) {
  const std::filesystem::path dir = std::filesystem::path(file).parent_path();
  for (auto it = n.begin(); it != n.end(); ++it) {
    MechanicsSpec::Hull h;
    h.name = it->first.as<std::string>();
    const YAML::Node m = it->second;
    if (!r.keys(m, {"body", "mesh", "placement", "scale"}, h.name)) continue;
    body(r, m, h.name, bodies, h.body);
    const dynamics::Transform X = r.pose(m["placement"], h.name + ".placement");
    const double scale = r.number(m["scale"], h.name + ".scale", 1.0);
    const bool scaleOk = scale >= 1e-3 && scale <= 1e3;  // mm to km: a scale of 1e200 is a typo
    if (!scaleOk) r.fail(m["scale"], h.name + ".scale", "the scale must be from 0.001 to 1000");
    if (!m["mesh"] || !m["mesh"].IsScalar()) {
      r.fail(m, h.name, "missing required key 'mesh' (an OBJ or STL file, relative to this YAML file)");
      continue;
    }
    const std::filesystem::path path = dir / m["mesh"].Scalar();
    try {
      h.mesh = std::make_shared<const forces::TriangleMesh>(
          forces::transformed(forces::readClosedMesh(path.lexically_normal().string()), X, scaleOk ? scale : 1.0));
    } catch (const forces::MeshError& e) {
      r.fail(m["mesh"], h.name + ".mesh", e.what());
      continue;
    }
    spec.hulls.push_back(std::move(h));
  }
}

void flows(const Reader& r, const YAML::Node& n, const std::set<std::string>& bodies,
           std::vector<MechanicsSpec::Flow>& out) {
  for (auto it = n.begin(); it != n.end(); ++it) {
    MechanicsSpec::Flow f;
    f.name = it->first.as<std::string>();
    const YAML::Node m = it->second;
    const std::string& k = f.name;
    if (!r.keys(m, {"body", "point", "frontal_area", "lateral_area", "length", "coefficients"}, k)) continue;
    body(r, m, k, bodies, f.body);
    f.point = r.vec3(m["point"], k + ".point", Vector3::Zero());
    f.areas.frontal = r.number(m["frontal_area"], k + ".frontal_area", 0.0, true);
    f.areas.lateral = r.number(m["lateral_area"], k + ".lateral_area", 0.0, true);
    f.areas.length = r.number(m["length"], k + ".length", 0.0);
    for (const char* a : {"frontal_area", "lateral_area", "length"})
      if (m[a] && !(r.number(m[a], k + "." + a, 0.0) >= 0)) r.fail(m[a], k + "." + a, "must be >= 0");
    if (const YAML::Node c = m["coefficients"]) {
      if (!r.keys(c, {"angle_deg", "cx", "cy", "cmz"}, k + ".coefficients")) continue;
      std::vector<double> angles;
      for (const char* key : {"angle_deg", "cx", "cy", "cmz"})
        if (!c[key]) r.fail(c, k + ".coefficients", std::string("missing required key '") + key + "' (a list of numbers)");
      if (!c["angle_deg"] || !c["cx"] || !c["cy"] || !c["cmz"]) continue;
      for (double a : r.numbers(c["angle_deg"], k + ".coefficients.angle_deg", 0)) angles.push_back(a * kDeg);
      try {
        f.coefficients = forces::FlowCoefficients(angles, r.numbers(c["cx"], k + ".coefficients.cx", 0),
                                                  r.numbers(c["cy"], k + ".coefficients.cy", 0),
                                                  r.numbers(c["cmz"], k + ".coefficients.cmz", 0));
      } catch (const std::invalid_argument& e) {
        r.fail(c, k + ".coefficients", e.what());
        continue;
      }
    }
    out.push_back(std::move(f));
  }
}

void dampers(const Reader& r, const YAML::Node& n, const std::set<std::string>& bodies, MechanicsSpec& spec) {
  for (auto it = n.begin(); it != n.end(); ++it) {
    MechanicsSpec::Damper d;
    d.name = it->first.as<std::string>();
    const YAML::Node m = it->second;
    const std::string& k = d.name;
    if (!r.keys(m, {"body", "point", "linear", "quadratic"}, k)) continue;
    body(r, m, k, bodies, d.body);
    d.point = r.vec3(m["point"], k + ".point", Vector3::Zero());
    // ([surge, sway, heave, roll, pitch, yaw]) => coefficients >= 0
    auto six = [&](const char* key, std::array<double, 6>& c) {
      if (!m[key]) return;
      const auto v = r.numbers(m[key], k + "." + key, 6);
      for (std::size_t i = 0; i < 6; ++i) {
        c[i] = v[i];
        if (!(v[i] >= 0)) {
          r.fail(m[key], k + "." + key, "coefficients must be >= 0 ([surge, sway, heave, roll, pitch, yaw])");
          break;
        }
      }
    };
    six("linear", d.coefficients.linear);
    six("quadratic", d.coefficients.quadratic);
    if (!m["linear"] && !m["quadratic"])
      r.fail(m, k, "give 'linear' and/or 'quadratic': [surge, sway, heave, roll, pitch, yaw]");
    spec.dampers.push_back(std::move(d));
  }
}

}  // namespace

void parseFloating(const Params& p, const MechanicsReport& report, const std::set<std::string>& bodies,
                   MechanicsSpec& spec) {
  auto defined = [&](const char* key) { return p.has(key) && p.node(key).IsDefined() && !p.node(key).IsNull(); };
  if (defined("water")) water(Reader{report, "water"}, p.node("water"), spec);
  if (defined("wind")) wind(Reader{report, "wind"}, p.node("wind"), spec);
  // (named providers) => a mapping of them, each read
  auto named = [&](const char* key, auto&& read) {
    if (!defined(key)) return;
    const Reader r{report, key};
    if (!p.node(key).IsMap()) {
      r.fail(p.node(key), "", "expected a mapping of named providers {name: {body, ...}}");
      return;
    }
    read(r, p.node(key));
  };
  named("hydrostatics", [&](const Reader& r, const YAML::Node& n) { hulls(r, n, p.mark("hydrostatics").file, bodies, spec); });
  named("wind_loads", [&](const Reader& r, const YAML::Node& n) { flows(r, n, bodies, spec.windLoads); });
  named("current_loads", [&](const Reader& r, const YAML::Node& n) { flows(r, n, bodies, spec.currentLoads); });
  named("damping", [&](const Reader& r, const YAML::Node& n) { dampers(r, n, bodies, spec); });
}


}  // namespace yardsim::scene
