// Registration of the scene type `multibody` (see multibody_model.hpp and docs/multibody_scenes.md).
#include "scene/mechanics_reader.hpp"
#include "scene/loop_gap_check.hpp"
#include "scene/yaml_source.hpp"
#include "mechanics/build.hpp"
#include "dynamics/model_builder.hpp"
#include "models/multibody/multibody_model.hpp"
#include "models/registry.hpp"

#include <cmath>
#include <string>

namespace yardsim::scene {

using mechanics::MechanicsSpec;
using mechanics::buildMechanics;
using mechanics::missingEnvironment;
using models::ElementRef;
using models::MultibodyModel;
using models::MultibodyOptions;
using models::ParamCheck;
using models::ParamKind;
using models::Params;
using models::PortSpec;
using models::TypeInfo;
using models::didYouMean;
namespace {

// (params) => the integrator's spec (method and its parameters; dt is the model's)
dynamics::IntegratorSpec integratorSpec(const Params& p) {
  dynamics::IntegratorSpec s;
  s.method = p.string("method");
  s.dt = p.number("dt");
  s.alpha = p.number("alpha");
  s.rhoInf = p.number("rho_inf");
  s.rtol = p.number("rtol");
  s.atol = p.number("atol");
  s.maxOrder = static_cast<int>(p.number("max_order"));
  return s;
}

MultibodyOptions options(const Params& p) {
  MultibodyOptions o;
  o.dt = p.number("dt");
  o.integrator = integratorSpec(p);
  o.driveBandwidth = p.number("drive_bandwidth");
  o.driveMaxEffort = p.number("drive_max_effort");
  o.driveTolerance = p.number("drive_tolerance");
  o.projectLoops = p.boolean("project_loops");
  o.equilibrium = p.boolean("equilibrium");
  return o;
}

// (params) => spec; the first problem thrown (used after validation, so it never throws)
MechanicsSpec parsed(const Params& p) {
  return parseMechanics(p, [](const std::string& param, const YAML::Node&, const std::string& key,
                              const std::string& msg) {
    throw std::invalid_argument(param + "." + key + ": " + msg);
  });
}

}  // namespace

YARDSIM_REGISTER_TYPE(multibody, TypeInfo{
    .name = "multibody",
    .summary = "a mechanically connected system of bodies and joints, stepped at dt (DTSS); "
               "actors drive its joints and load its bodies through `setpoint`",
    .params =
        {
            {"bodies", ParamKind::Map, true, "", "",
             "name: {parent, joint: {type, axis, q0|q0_deg, v0}, placement: {xyz, rpy_deg}, mass, "
             "com, inertia, geometry, added_mass: {matrix, about} or {hull, rho}}"},
            {"loops", ParamKind::Any, false, "{}", "",
             "name: {body_a, frame_a, body_b, frame_b, constrain: point|axis|weld}"},
            {"ropes", ParamKind::Any, false, "{}", "",
             "name: {path: [{body, point}, ...], EA, L0, damping, parts, min_length, mbl}"},
            {"equalizers", ParamKind::Any, false, "{}", "",
             "name: {sheave: {body, point}, branches: [[{body, point}, ...], ...], EA, L0, damping, "
             "min_length, mbl}"},
            {"loads", ParamKind::Any, false, "{}", "",
             "name: {body, point, frame: world|body, series: [[t, fx, fy, fz, mx, my, mz], ...]}"},
            {"watch", ParamKind::Any, false, "{}", "",
             "name: {channel: <element>.<quantity>, above | below: threshold} (a `crossed` event)"},
            {"gravity", ParamKind::NumberList, false, "[0, 0, -9.81]", "m/s^2", "gravity vector"},
            {"water", ParamKind::Any, false, "~", "",
             "{density, level, depth, waves: [{height, period, direction_deg, phase_deg} | {spectrum, hs, tp, gamma, "
             "direction_deg, spreading_s, seed, components}], wave_start, wave_ramp, "
             "current: {speed, direction_deg, profile: [[z, factor], ...]}}"},
            {"wind", ParamKind::Any, false, "~", "",
             "{speed, direction_deg, reference_height, profile: uniform|power_law|npd, exponent, "
             "averaging_time, air_density}"},
            {"hydrostatics", ParamKind::Any, false, "{}", "",
             "name: {body, mesh: file.obj|.stl, placement: {xyz, rpy_deg}, scale}"},
            {"wind_loads", ParamKind::Any, false, "{}", "",
             "name: {body, point, frontal_area, lateral_area, length, coefficients: {angle_deg, cx, cy, cmz}}"},
            {"current_loads", ParamKind::Any, false, "{}", "",
             "name: {body, point, frontal_area, lateral_area, length, coefficients: {angle_deg, cx, cy, cmz}}"},
            {"damping", ParamKind::Any, false, "{}", "",
             "name: {body, point, linear: [6], quadratic: [6]} (surge, sway, heave, roll, pitch, yaw)"},
            {"hydrodynamics", ParamKind::Any, false, "{}", "",
             "name: {body, method: impulse_response|rankine_td, hull, response, solver, headings_deg, dt, memory, "
             "settings, cache, excitation}"},
            {"dt", ParamKind::Number, true, "", "s", "integrator step"},
            {"method", ParamKind::String, false, "rk4", "",
             "integration method (docs/integrators.md): explicit_euler, semi_implicit_euler, rk4, ab2, "
             "ab3, ab4, hht, generalized_alpha, cvode_bdf, cvode_adams, arkode_erk, arkode_dirk, arkode_imex"},
            {"alpha", ParamKind::Number, false, "-0.1", "", "hht: alpha in [-1/3, 0]"},
            {"rho_inf", ParamKind::Number, false, "0.8", "", "generalized_alpha: rho_inf in [0, 1]"},
            {"rtol", ParamKind::Number, false, "1e-6", "", "adaptive methods: relative tolerance"},
            {"atol", ParamKind::Number, false, "1e-8", "", "adaptive methods: absolute tolerance"},
            {"max_order", ParamKind::Number, false, "0", "", "cvode_bdf, cvode_adams: maximum order (0: 5, 12)"},
            {"drive_bandwidth", ParamKind::Number, false, "0", "rad/s",
             "joint servo bandwidth (0: min(10, 0.1/dt))"},
            {"drive_max_effort", ParamKind::Number, false, "0", "N m or N",
             "joint servo force bound (0: unbounded)"},
            {"drive_tolerance", ParamKind::Number, false, "1e-3", "rad or m",
             "a drive has reached its target within this"},
            {"project_loops", ParamKind::Boolean, false, "true", "",
             "project q and v onto the loop constraints after every step"},
            {"equilibrium", ParamKind::Boolean, false, "false", "",
             "start from static equilibrium (v = 0) found from the given initial state"},
        },
    .ports = [](const Params&) {
      return std::vector<PortSpec>{{"setpoint", "setpoint", true, true},
                                   {"event", "mechanics_event", false}};
    },
    .create = [](const std::string& n, const Params& p) -> std::unique_ptr<devs::AtomicBase> {
      return std::make_unique<MultibodyModel>(n, buildMechanics(parsed(p)), options(p));
    },
    .check =
        [](const Params& p, ParamCheck& c) {
          if (!(p.number("dt") > 0)) c.error("dt", "must be > 0 s");
          // (max_order as written) => refused unless a whole number from 0 to 12, before any cast
          // to int
          const double maxOrder = p.number("max_order");
          if (!(maxOrder >= 0 && maxOrder <= 12 && maxOrder == std::floor(maxOrder)))
            c.error("max_order",
                    "expected a whole number from 0 to 12 (0: the method's highest order), got " +
                        p.node("max_order").Scalar());
          else
            for (const auto& problem : dynamics::checkIntegratorSpec(integratorSpec(p))) {
              if (problem.key == "dt") continue;
              const std::string hint =
                  problem.key == "method"
                      ? didYouMean(p.string("method"), dynamics::integratorMethodNames())
                      : "";
              c.error(problem.key, problem.message + (hint.empty() ? "" : " (" + hint + ")"));
            }
          const MechanicsSpec spec = parseMechanics(
              p, [&](const std::string& param, const YAML::Node& at, const std::string& key,
                     const std::string& msg) { c.errorAt(param, at, key, msg); });
          if (c.failed()) return;
          if (const std::string missing = missingEnvironment(spec); !missing.empty()) {
            c.error(spec.wind ? "current_loads" : "wind_loads", missing);
            return;
          }
          try {
            for (const auto& [name, message] : openLoops(buildMechanics(spec))) c.errorAt("loops", mapKey(p.node("loops"), name), name, message);
          } catch (const dynamics::ModelError& e) {
            c.error("bodies", e.what());
          }
        },
    .feedthrough = {},
    .elements =
        [](const Params& p) {
          std::vector<ElementRef> out;
          const MechanicsSpec spec = parsed(p);
          for (const auto& b : spec.bodies) {
            out.push_back({"body", b.name, ""});
            out.push_back({"joint", b.jointName.empty() ? b.name + "_joint" : b.jointName, ""});
          }
          for (const auto& r : spec.ropes) out.push_back({"rope", r.name, ""});
          for (const auto& c : spec.providers)  // (crane ropes with mass) => wire actors' too
            if (c.winch) out.push_back({"rope", c.name, ""});
          for (const auto& e : spec.equalizers) out.push_back({"equalizer", e.name, ""});
          for (const auto& w : spec.watches) out.push_back({"watch", w.name, ""});
          for (const auto& h : spec.hulls) out.push_back({"hydrostatics", h.name, ""});
          for (const auto& w : spec.windLoads) out.push_back({"wind_load", w.name, ""});
          for (const auto& c : spec.currentLoads) out.push_back({"current_load", c.name, ""});
          for (const auto& d : spec.dampers) out.push_back({"damping", d.name, ""});
          for (const auto& h : spec.hydrodynamics) out.push_back({"hydrodynamics", h.name, ""});
          return out;
        }});

}  // namespace yardsim::scene
