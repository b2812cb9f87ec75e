#include "dynamics/integrators/factory.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "dynamics/integrators/adams_bashforth.hpp"
#include "dynamics/integrators/arkode.hpp"
#include "dynamics/integrators/cvode.hpp"
#include "dynamics/integrators/explicit_euler.hpp"
#include "dynamics/integrators/generalized_alpha.hpp"
#include "dynamics/integrators/hht.hpp"
#include "dynamics/integrators/rk4.hpp"
#include "dynamics/integrators/semi_implicit_euler.hpp"
#include "dynamics/multibody_system.hpp"

namespace yardsim::dynamics {

namespace {
constexpr double kInf = kUnconditionallyStable;
// name, summary, order, adaptive, implicit, index 3, omega*dt limit on the imaginary axis
constexpr MethodInfo kMethods[] = {
    {"explicit_euler", "explicit (forward) Euler, fixed step", 1, false, false, false, 0.0},
    {"semi_implicit_euler", "semi-implicit (symplectic) Euler, fixed step", 1, false, false, false, 2.0},
    {"rk4", "classical Runge-Kutta, fixed step", 4, false, false, false, 2.8284271247461903},
    {"ab2", "Adams-Bashforth order 2 (RK4 start), fixed step", 2, false, false, false, 0.0},
    {"ab3", "Adams-Bashforth order 3 (RK4 start), fixed step", 3, false, false, false, 0.7236},
    {"ab4", "Adams-Bashforth order 4 (RK4 start), fixed step", 4, false, false, false, 0.4294},
    {"hht", "HHT-alpha, implicit, index-3 loops, fixed step", 2, false, true, true, kInf},
    {"generalized_alpha", "generalized-alpha (Chung-Hulbert), implicit, index-3 loops, fixed step", 2, false, true,
     true, kInf},
    {"cvode_bdf", "SUNDIALS CVODE, BDF orders 1-5, Newton with dense LU, adaptive", 5, true, true, false, kInf},
    {"cvode_adams", "SUNDIALS CVODE, Adams-Moulton orders 1-12, adaptive", 12, true, true, false, kInf},
    {"arkode_erk", "SUNDIALS ARKODE ARKStep, explicit Runge-Kutta (order 4), adaptive", 4, true, false, false, kInf},
    {"arkode_dirk", "SUNDIALS ARKODE ARKStep, diagonally implicit Runge-Kutta (order 4), adaptive", 4, true, true,
     false, kInf},
    {"arkode_imex", "SUNDIALS ARKODE ARKStep, IMEX Runge-Kutta (ARK4(3)6L), adaptive", 4, true, true, false, kInf},
};

std::string number(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}
}  // namespace

std::span<const MethodInfo> integratorMethods() { return kMethods; }

const MethodInfo* findMethod(std::string_view name) {
  for (const MethodInfo& m : kMethods)
    if (m.name == name) return &m;
  return nullptr;
}

std::vector<std::string> integratorMethodNames() {
  std::vector<std::string> out;
  for (const MethodInfo& m : kMethods) out.emplace_back(m.name);
  return out;
}

std::vector<SpecProblem> checkIntegratorSpec(const IntegratorSpec& s) {
  std::vector<SpecProblem> out;
  const MethodInfo* m = findMethod(s.method);
  if (m == nullptr) {
    std::string names;
    for (const MethodInfo& k : kMethods) names += (names.empty() ? "" : ", ") + std::string(k.name);
    out.push_back({"method", "unknown integration method '" + s.method + "'; expected one of " + names});
    return out;
  }
  if (!(s.dt > 0) || !std::isfinite(s.dt)) out.push_back({"dt", "expected a positive step in seconds, got " + number(s.dt)});
  if (s.method == "hht" && !(s.alpha >= -1.0 / 3.0 && s.alpha <= 0.0))
    out.push_back({"alpha", "HHT needs alpha in [-1/3, 0], got " + number(s.alpha)});
  if (s.method == "generalized_alpha" && !(s.rhoInf >= 0.0 && s.rhoInf <= 1.0))
    out.push_back({"rho_inf", "generalized-alpha needs rho_inf in [0, 1], got " + number(s.rhoInf)});
  if (m->adaptive) {
    if (!(s.rtol > 0 && s.rtol < 1)) out.push_back({"rtol", "expected a relative tolerance in (0, 1), got " + number(s.rtol)});
    if (!(s.atol > 0)) out.push_back({"atol", "expected a positive absolute tolerance, got " + number(s.atol)});
    if (s.maxStep < 0) out.push_back({"max_step", "expected a step >= 0 s (0: unbounded), got " + number(s.maxStep)});
  }
  if (s.method == "cvode_bdf" && (s.maxOrder < 0 || s.maxOrder > 5))
    out.push_back({"max_order", "CVODE BDF orders are 1 to 5 (0: 5), got " + std::to_string(s.maxOrder)});
  if (s.method == "cvode_adams" && (s.maxOrder < 0 || s.maxOrder > 12))
    out.push_back({"max_order", "CVODE Adams orders are 1 to 12 (0: 12), got " + std::to_string(s.maxOrder)});
  if (m->implicit && !m->adaptive) {
    if (!(s.newtonTol > 0)) out.push_back({"newton_tol", "expected a positive tolerance, got " + number(s.newtonTol)});
    if (s.maxNewton < 2) out.push_back({"max_newton", "expected at least 2 iterations, got " + std::to_string(s.maxNewton)});
  }
  if (s.baumgarteAlpha < 0 || s.baumgarteBeta < 0)
    out.push_back({"baumgarte", "Baumgarte gains must be >= 0 (0: 0.2/dt)"});
  return out;
}

std::unique_ptr<Integrator> makeIntegrator(const IntegratorSpec& s, const Model& model) {
  const std::vector<SpecProblem> problems = checkIntegratorSpec(s);
  if (!problems.empty())
    throw std::invalid_argument("integrator." + problems.front().key + ": " + problems.front().message);
  // (method name, parameters) => the integrator
  if (s.method == "explicit_euler") return std::make_unique<ExplicitEuler>(model);
  if (s.method == "semi_implicit_euler") return std::make_unique<SemiImplicitEuler>(model);
  if (s.method == "rk4") return std::make_unique<Rk4>(model);
  if (s.method == "ab2") return std::make_unique<AdamsBashforth>(model, 2);
  if (s.method == "ab3") return std::make_unique<AdamsBashforth>(model, 3);
  if (s.method == "ab4") return std::make_unique<AdamsBashforth>(model, 4);
  if (s.method == "hht")
    return std::make_unique<GeneralizedAlpha>(model, hhtParameters(s.alpha), "hht", s.newtonTol, s.maxNewton);
  if (s.method == "generalized_alpha")
    return std::make_unique<GeneralizedAlpha>(model, chungHulbert(s.rhoInf), "generalized_alpha", s.newtonTol,
                                              s.maxNewton);
  if (s.method == "cvode_bdf" || s.method == "cvode_adams") return std::make_unique<Cvode>(model, s);
  return std::make_unique<Arkode>(model, s);
}

void configureLoopStabilization(const IntegratorSpec& s, MultibodySystem& system) {
  const bool indexThree = findMethod(s.method) != nullptr && findMethod(s.method)->indexThree;
  system.setProjection(s.loops == LoopStabilization::Projection);
  Baumgarte b;
  if (s.loops == LoopStabilization::Baumgarte && !indexThree && s.dt > 0) {
    b.alpha = s.baumgarteAlpha > 0 ? s.baumgarteAlpha : 0.2 / s.dt;
    b.beta = s.baumgarteBeta > 0 ? s.baumgarteBeta : 0.2 / s.dt;
  }
  system.setBaumgarte(b);
}

}  // namespace yardsim::dynamics
