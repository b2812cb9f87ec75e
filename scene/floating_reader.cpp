#include "scene/floating_reader.hpp"

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <map>

#include "scene/mechanics_reader.hpp"
#include "forces/geometry/mesh_io.hpp"
#include "forces/hydro/hydrodynamics_methods.hpp"
#include "forces/hydro/impulse_response_cache.hpp"
#include "forces/hydro/impulse_response_force.hpp"
#include "forces/hydro/irregular_sea.hpp"
#include "scene/spec_reader.hpp"
#include "scene/wind_reader.hpp"

namespace yardsim::scene {

using mechanics::MechanicsSpec;
using models::Params;
using models::didYouMean;
namespace {

using dynamics::Vector3;
using spec::angle;
using spec::kDeg;
using spec::Reader;
using spec::wholeNumber;

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

// ({spectrum, hs, tp, gamma, direction_deg, spreading_s, seed, components, cutoff}) => the sea's
// components appended to spec.waves (docs/hydrodynamics.md, "Irregular seas")
void irregular(const Reader& r, const YAML::Node& n, const std::string& key, const forces::WaterProperties& w,
               MechanicsSpec& spec) {
  if (!r.keys(n, {"spectrum", "hs", "tp", "gamma", "direction", "direction_deg", "spreading_s", "seed", "components", "cutoff"},
              key))
    return;
  forces::hydro::IrregularSea sea;
  const YAML::Node kind = n["spectrum"];
  try {
    sea.spectrum = forces::hydro::spectrumKind(kind.IsScalar() ? kind.Scalar() : "");
  } catch (const std::invalid_argument& e) {
    r.fail(kind, key + ".spectrum", std::string(e.what()) + " " +
               didYouMean(kind.IsScalar() ? kind.Scalar() : "", {"jonswap", "pierson_moskowitz"}));
    return;
  }
  if (n["gamma"] && sea.spectrum != forces::hydro::SpectrumKind::Jonswap)
    r.fail(n["gamma"], key + ".gamma", "'gamma' goes with spectrum: jonswap (Pierson-Moskowitz has none)");
  sea.hs = r.number(n["hs"], key + ".hs", 0.0, true);
  sea.tp = r.number(n["tp"], key + ".tp", 0.0, true);
  sea.gamma = r.number(n["gamma"], key + ".gamma", 3.3);
  sea.direction = angle(r, n, key, "direction");
  sea.spreadingS = r.number(n["spreading_s"], key + ".spreading_s", 0.0);
  sea.seed = static_cast<std::uint64_t>(wholeNumber(r, n["seed"], key + ".seed", 1, 0, 2147483647));
  sea.components = static_cast<int>(wholeNumber(r, n["components"], key + ".components", 200, 1, 100000));
  sea.cutoff = r.number(n["cutoff"], key + ".cutoff", 0.0);
  // (each value at its own node) => the first word of the message names the key
  const std::pair<const char*, bool> checks[] = {{"hs", sea.hs > 0},
                                                 {"tp", sea.tp > 0},
                                                 {"gamma", sea.gamma >= 1 && sea.gamma <= 20},
                                                 {"spreading_s", sea.spreadingS == 0 || (sea.spreadingS > 0 && sea.spreadingS <= 1000)},
                                                 {"cutoff", sea.cutoff >= 0}};
  if (!n["hs"] || !n["tp"]) return;  // (reported above)
  try {
    auto waves = forces::hydro::irregularWaves(sea);
    forces::AiryWaves(w, waves);  // (every component on this water) => not breaking
    spec.waves.insert(spec.waves.end(), waves.begin(), waves.end());
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    for (const auto& [name, ok] : checks)
      if (!ok && n[name]) return r.fail(n[name], key + "." + name, what.substr(what.find(": ") + 2));
    if (what.rfind("cutoff: ", 0) == 0 && n["cutoff"])
      return r.fail(n["cutoff"], key + ".cutoff", what.substr(8));
    r.fail(n, key, what);
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
    if (ws.IsMap()) {
      irregular(r, ws, "waves", w, spec);
    } else if (!ws.IsSequence()) {
      r.fail(ws, "waves", "expected a list of regular waves [{height, period, direction_deg, phase_deg}, ...] "
                          "and irregular seas {spectrum, hs, tp, ...}, or one irregular sea");
    } else {
      for (std::size_t i = 0; i < ws.size(); ++i) {
        const std::string k = "waves[" + std::to_string(i) + "]";
        if (ws[i].IsMap() && ws[i]["spectrum"]) {
          irregular(r, ws[i], k, w, spec);
          continue;
        }
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

// (mesh path relative to the YAML file, placement, scale) => the hull in the body frame
void hulls(const Reader& r, const YAML::Node& n, const std::string& file, const std::set<std::string>& bodies,
           MechanicsSpec& spec) {
  const std::filesystem::path dir = std::filesystem::path(file).parent_path();
  for (auto it = n.begin(); it != n.end(); ++it) {
    MechanicsSpec::Hull h;
    h.name = it->first.as<std::string>();
    const YAML::Node m = it->second;
    if (!r.keys(m, {"body", "mesh", "placement", "scale", "froude_krylov"}, h.name)) continue;
    if (const YAML::Node fk = m["froude_krylov"]) {
      const std::string v = fk.IsScalar() ? fk.Scalar() : "";
      if (v == "none")
        h.incidentPressure = false;
      else if (v != "nonlinear")
        r.fail(
            fk, h.name + ".froude_krylov",
            "expected nonlinear (clipped at the incident surface, its pressure integrated) or none "
            "(clipped at the still-water level; the waves' force from the body's hydrodynamics)");
    }
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

// (a method, its hull, response or solver, headings, dt, memory, settings, cache, excitation)
// => the provider's build on the scene's sea; for impulse_response the response's A_inf on the
// body's left-hand side (docs/hydrodynamics.md, "Scene keys"); per body why its wave force lacks Froude-Krylov
void hydrodynamics(const Reader& r, const YAML::Node& n, const std::string& file, const std::set<std::string>& bodies,
                   MechanicsSpec& spec, std::map<std::string, std::string>& noFroudeKrylov) {
  namespace hydro = forces::hydro;
  const std::filesystem::path dir = std::filesystem::path(file).parent_path();
  // (path relative to the YAML file) => the path
  auto path = [&](const YAML::Node& v) {
    std::filesystem::path f(v.Scalar());
    return (f.is_relative() ? dir / f : f).lexically_normal();
  };
  for (auto it = n.begin(); it != n.end(); ++it) {
    MechanicsSpec::Hydrodynamics h;
    h.name = it->first.as<std::string>();
    const YAML::Node m = it->second;
    const std::string& k = h.name;
    if (!r.keys(m, {"body", "method", "hull", "response", "solver", "headings", "headings_deg", "dt", "memory",
                    "settings", "cache", "excitation"}, k))
      continue;
    body(r, m, k, bodies, h.body);
    const YAML::Node method = m["method"];
    if (!method || !method.IsScalar()) {
      r.fail(method ? method : m, k + ".method", "missing required key 'method' (impulse_response or rankine_td)");
      continue;
    }
    const std::string how = method.Scalar();
    // (hull, headings, dt, memory, settings) => the request the solvers and checks see
    hydro::HydrodynamicsRequest q;
    q.water = spec.water;
    q.dt = r.number(m["dt"], k + ".dt", q.dt);
    q.memory = r.number(m["memory"], k + ".memory", q.memory);
    if (!(q.dt > 0)) r.fail(m["dt"], k + ".dt", "the response's sample spacing must be > 0 s");
    if (!(q.memory > q.dt)) r.fail(m["memory"], k + ".memory", "the radiation memory must be longer than dt");
    if (m["headings_deg"]) {
      for (double b : r.numbers(m["headings_deg"], k + ".headings_deg", 0)) q.headings.push_back(b * kDeg);
    } else if (m["headings"]) {
      q.headings = r.numbers(m["headings"], k + ".headings", 0);
    }
    if (const YAML::Node st = m["settings"]) {
      if (!st.IsMap()) r.fail(st, k + ".settings", "expected a mapping of the method's numbers {name: value}");
      else
        for (auto s = st.begin(); s != st.end(); ++s)
          q.settings[s->first.Scalar()] = r.number(s->second, k + ".settings." + s->first.Scalar(), 0.0);
    }
    for (const auto& b : spec.bodies)
      if (b.name == h.body && b.parent == "world")
        q.X_WB = b.X_PJ * (b.q0.empty() ? dynamics::Transform::identity() : dynamics::jointTransform(b.joint, b.q0.data()));
    if (const YAML::Node hull = m["hull"]) {
      try {
        q.hull = std::make_shared<const forces::TriangleMesh>(forces::readClosedMesh(path(hull).string()));
      } catch (const forces::MeshError& e) {
        r.fail(hull, k + ".hull", e.what());
        continue;
      }
    }
    const bool excitation = m["excitation"] ? m["excitation"].as<std::string>() != "false" : true;
    if (m["excitation"] && !m["excitation"].IsScalar()) r.fail(m["excitation"], k + ".excitation", "expected true or false");
    // (the registered check, on the sea of this file's water) => its problems at the entry
    auto check = [&](const hydro::HydrodynamicsCheck& c) {
      if (!c) return true;
      bool ok = true;
      for (const std::string& problem : c(q, forces::AiryWaves(spec.water, spec.waves))) {
        r.fail(m, k, problem);
        ok = false;
      }
      return ok;
    };
    if (how != "impulse_response") {
      const hydro::TimeDomainMethod* td = hydro::timeDomainMethod(how);
      if (!td) {
        if (how == "rankine_td") r.fail(method, k + ".method", "rankine_td: not available in this build");
        else r.fail(method, k + ".method", "unknown method '" + how + "' " + didYouMean(how, {"impulse_response", "rankine_td"}));
        continue;
      }
      for (const char* key : {"response", "solver", "cache"})
        if (m[key]) r.fail(m[key], k + "." + key, std::string("'") + key + "' goes with method: impulse_response");
      if (!q.hull) r.fail(m, k, "missing required key 'hull' (the hull mesh in the body frame, .obj or .stl)");
      if (!q.hull || !check(td->check)) continue;
      const auto fk = q.settings.find("froude_krylov");
      noFroudeKrylov[h.body] = fk != q.settings.end() && fk->second != 0 ? "" : "'" + k + "' has settings.froude_krylov 0";
      if (td->addedMass) {  // (A_inf) => the body's added mass, unless the body has its own
        try {
          const auto aInf = td->addedMass(q);
          for (auto& b : spec.bodies)
            if (b.name == h.body) {
              if (b.addedMass || b.addedMassHull)
                r.fail(m, k, "body '" + b.name + "' has an added_mass block; " + how +
                                 " puts its own A_inf on the left-hand side: remove one of the two");
              b.addedMass = aInf;
              b.addedMassAbout = Vector3::Zero();
            }
        } catch (const std::exception& e) {
          r.fail(m, k, e.what());
          continue;
        }
      }
      h.build = [build = td->build, q](const std::string& name, const dynamics::Model& model, int b,
                                       std::shared_ptr<const forces::AiryWaves> sea) { return build(name, model, b, q, sea); };
      if (td->runCheck) h.runCheck = [c = td->runCheck, q](double until) { return c(q, until); };
      if (td->marchingStep) h.marchingStep = [c = td->marchingStep, q] { return c(q); };
      spec.hydrodynamics.push_back(std::move(h));
      continue;
    }
    // (impulse_response) => from a file, or from the cache by key, or solved and cached
    std::shared_ptr<const hydro::ImpulseResponse> response;
    if (m["response"].IsDefined() == m["hull"].IsDefined()) {
      r.fail(m, k, "give exactly one of 'response' (an impulse-response file) and 'hull' (a mesh to compute it from)");
      continue;
    }
    try {
      if (const YAML::Node given = m["response"]) {
        response = std::make_shared<const hydro::ImpulseResponse>(hydro::readImpulseResponse(path(given)));
      } else {
        const std::string solverName = m["solver"] ? m["solver"].Scalar() : "";
        const hydro::ImpulseResponseSolver* solver = hydro::impulseResponseSolver(solverName);
        if (!solver) {
          const auto names = hydro::impulseResponseSolverNames();
          std::string known;
          for (const auto& name : names) known += (known.empty() ? "" : ", ") + name;
          r.fail(m["solver"] ? m["solver"] : m, k + (m["solver"] ? ".solver" : ""),
                 names.empty() ? "no impulse-response solver in this build (give 'response': a file)"
                               : (solverName.empty() ? "several solvers: name one with 'solver' (" : "unknown solver (") +
                                     known + ")");
          continue;
        }
        if (!check(solver->check)) continue;
        response = hydro::cachedOrSolved(q, *solver, m["cache"] ? path(m["cache"]) : hydro::impulseResponseCacheDir());
      }
    } catch (const std::exception& e) {
      r.fail(m["response"] ? m["response"] : m, k + (m["response"] ? ".response" : ""), e.what());
      continue;
    }
    if (excitation && !spec.waves.empty() && response->headings.empty()) {
      r.fail(m, k, "the sea has waves but the impulse response has no excitation (no headings); compute it with "
                   "headings_deg or set excitation: false");
      continue;
    }
    noFroudeKrylov[h.body] = !excitation ? (spec.waves.empty() ? "" : "'" + k + "' has excitation: false in waves")
                             : response->froudeKrylov ? "" : "the response of '" + k + "' is diffraction only";
    // (A_inf) => the body's added mass, unless the body has its own
    for (auto& b : spec.bodies)
      if (b.name == h.body) {
        if (b.addedMass || b.addedMassHull)
          r.fail(m, k, "body '" + b.name + "' has an added_mass block; the impulse response puts its own A_inf on "
                       "the left-hand side: remove one of the two");
        b.addedMass = response->aInf;
        b.addedMassAbout = Vector3::Zero();
      }
    if (excitation && response->excitationWindow > 0)
      h.seaCheck = [response](const forces::AiryWaves& sea) { return hydro::checkResolvedSea(*response, sea); };
    h.build = [response, excitation](const std::string& name, const dynamics::Model& model, int b,
                                     std::shared_ptr<const forces::AiryWaves> sea) -> std::unique_ptr<forces::ForceProvider> {
      return std::make_unique<hydro::ImpulseResponseForce>(name, model, b, response, excitation ? sea : nullptr);
    };
    spec.hydrodynamics.push_back(std::move(h));
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
    f.point = r.length3(m["point"], k + ".point", Vector3::Zero());
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
    d.point = r.length3(m["point"], k + ".point", Vector3::Zero());
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
  if (defined("wind")) readWind(Reader{report, "wind"}, p.node("wind"), spec);
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
  std::map<std::string, std::string> noFroudeKrylov;
  named("hydrodynamics",
        [&](const Reader& r, const YAML::Node& n) { hydrodynamics(r, n, p.mark("hydrodynamics").file, bodies, spec, noFroudeKrylov); });
  // (a hull without the incident pressure) => the body's hydrodynamics must bring the waves' force
  if (!defined("hydrostatics")) return;
  const Reader r{report, "hydrostatics"};
  for (const auto& h : spec.hulls) {
    if (h.incidentPressure) continue;
    bool driven = false;
    for (const auto& d : spec.hydrodynamics) driven = driven || d.body == h.body;
    const YAML::Node at = p.node("hydrostatics")[h.name]["froude_krylov"];
    const std::string none = "none leaves the waves' force to the body's hydrodynamics, ";
    if (!driven)
      r.fail(at, h.name + ".froude_krylov", none + "and body '" + h.body +
                 "' has no hydrodynamics block here (with an excitation that includes Froude-Krylov)");
    else if (const std::string& why = noFroudeKrylov[h.body]; !why.empty())
      r.fail(at, h.name + ".froude_krylov", none + "but " + why + ": expected an excitation that includes "
                 "Froude-Krylov (a response computed with settings: {froude_krylov: 1}), or froude_krylov: nonlinear");
  }
}

}  // namespace yardsim::scene
