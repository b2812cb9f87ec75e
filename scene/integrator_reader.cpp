#include "scene/integrator_reader.hpp"

#include <algorithm>
#include <limits>

#include "models/params.hpp"
#include "scene/yaml_source.hpp"

namespace yardsim::scene {

using models::Diagnostics;
using models::ParamKind;
using models::didYouMean;
using models::hasKind;

namespace {

// key, the methods that use it (empty: every method)
struct KeyUse {
  const char* key;
  std::vector<std::string> methods;
};
const std::vector<KeyUse>& keyUses() {
  static const std::vector<KeyUse> uses{
      {"method", {}},
      {"dt", {}},
      {"alpha", {"hht"}},
      {"rho_inf", {"generalized_alpha"}},
      {"rtol", {"cvode_bdf", "cvode_adams", "arkode_erk", "arkode_dirk", "arkode_imex"}},
      {"atol", {"cvode_bdf", "cvode_adams", "arkode_erk", "arkode_dirk", "arkode_imex"}},
      {"max_step", {"cvode_bdf", "cvode_adams", "arkode_erk", "arkode_dirk", "arkode_imex"}},
      {"max_order", {"cvode_bdf", "cvode_adams"}},
      {"newton_tol", {"hht", "generalized_alpha"}},
      {"max_newton", {"hht", "generalized_alpha"}},
      {"loops", {}},
      {"baumgarte_alpha", {}},
      {"baumgarte_beta", {}},
      {"stiffness_check", {}},  // read by the scene loader (docs/numerics.md)
  };
  return uses;
}

}  // namespace

dynamics::IntegratorSpec parseIntegratorSpec(const YAML::Node& n, const std::string& f, Diagnostics& d) {
  dynamics::IntegratorSpec spec;
  spec.method = "none";
  if (!n.IsMap() || !n["method"] || !n["method"].IsScalar()) {
    d.error(markOf(n, f), "integrator", "expected {method: name, dt: seconds, ...}");
    return spec;
  }
  // (keys) => unknown ones reported with "did you mean"
  std::vector<std::string> allowed;
  for (const KeyUse& u : keyUses()) allowed.emplace_back(u.key);
  checkKeys(n, allowed, f, "integrator", d);
  // (method) => one of the table's names
  const YAML::Node method = n["method"];
  spec.method = method.Scalar();
  if (dynamics::findMethod(spec.method) == nullptr) {
    const std::vector<std::string> names = dynamics::integratorMethodNames();
    std::string list;
    for (const auto& m : names) list += (list.empty() ? "" : ", ") + m;
    d.error(markOf(method, f), "integrator.method",
            "unknown integration method '" + spec.method + "'; expected one of: " + list,
            didYouMean(spec.method, names));
    return spec;
  }
  // (numbers) => spec fields, each checked for its kind
  auto number = [&](const char* key, double& out) {
    const YAML::Node v = n[key];
    if (!v) return;
    if (!hasKind(v, ParamKind::Number))
      d.error(markOf(v, f), std::string("integrator.") + key, "expected a number, got " + shown(v));
    else
      out = v.as<double>();
  };
  auto integer = [&](const char* key, int& out) {
    const YAML::Node v = n[key];
    if (!v) return;
    // (value) => an int, or an error when it is no integer or beyond an int's range (not a throw)
    if (!hasKind(v, ParamKind::Integer))
      d.error(markOf(v, f), std::string("integrator.") + key, "expected an integer, got " + shown(v));
    else if (const long long k = v.as<long long>();
             k < std::numeric_limits<int>::min() || k > std::numeric_limits<int>::max())
      d.error(markOf(v, f), std::string("integrator.") + key,
              "expected an integer of magnitude at most 2147483647, got " + shown(v));
    else
      out = static_cast<int>(k);
  };
  number("alpha", spec.alpha);
  number("rho_inf", spec.rhoInf);
  number("rtol", spec.rtol);
  number("atol", spec.atol);
  number("max_step", spec.maxStep);
  integer("max_order", spec.maxOrder);
  number("newton_tol", spec.newtonTol);
  integer("max_newton", spec.maxNewton);
  number("baumgarte_alpha", spec.baumgarteAlpha);
  number("baumgarte_beta", spec.baumgarteBeta);
  if (const YAML::Node v = n["loops"]) {
    const std::vector<std::string> kinds{"projection", "baumgarte", "none"};
    const std::string s = v.IsScalar() ? v.Scalar() : "";
    if (s == "projection") spec.loops = dynamics::LoopStabilization::Projection;
    else if (s == "baumgarte") spec.loops = dynamics::LoopStabilization::Baumgarte;
    else if (s == "none") spec.loops = dynamics::LoopStabilization::None;
    else
      d.error(markOf(v, f), "integrator.loops", "expected projection, baumgarte or none, got " + shown(v),
              didYouMean(s, kinds));
  }
  // (values) => ranges of the method's parameters, at the offending key; dt is the caller's (the
  // run settings read it with its range, a wp run sets its own): one error for a bad dt
  for (const auto& p : dynamics::checkIntegratorSpec(spec)) {
    if (p.key == "dt") continue;
    const YAML::Node at = n[p.key];
    d.error(markOf(at ? at : n, f), "integrator." + p.key, p.message);
  }
  // (keys the method does not use) => warnings
  for (const KeyUse& u : keyUses()) {
    if (!n[u.key] || u.methods.empty()) continue;
    if (std::find(u.methods.begin(), u.methods.end(), spec.method) != u.methods.end()) continue;
    std::string users;
    for (const auto& m : u.methods) users += (users.empty() ? "" : ", ") + m;
    d.warning(markOf(n[u.key], f), std::string("integrator.") + u.key,
              std::string("'") + u.key + "' is a parameter of " + users + "; method " + spec.method + " ignores it");
  }
  return spec;
}

}  // namespace yardsim::scene
