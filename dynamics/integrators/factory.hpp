#pragma once
// Choosing an integrator by name: the parameters of every method (IntegratorSpec), the table of
// methods with their order and stability limit, and makeIntegrator(). See docs/integrators.md.

#include <limits>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "dynamics/integrators/integrator.hpp"
#include "dynamics/model.hpp"

namespace yardsim::dynamics {

class MultibodySystem;

/// How a closed loop stays on its constraints with a method that integrates the index-1 form
/// (explicit and adaptive methods). HHT and generalized-alpha solve the index-3 form instead.
enum class LoopStabilization {
  Projection,  ///< project q and v onto g(q) = 0, J v = 0 after every step (projection.hpp)
  Baumgarte,   ///< add -2 alpha J v - beta^2 g(q) to the acceleration constraint
  None,        ///< neither: the residual drifts
};

struct IntegratorSpec {
  std::string method = "rk4";  ///< one of integratorMethods()
  double dt = 0.0;             ///< s: fixed step, or the DTSS step inside which an adaptive method runs
  double alpha = -0.1;         ///< hht: alpha in [-1/3, 0] (0: trapezoidal rule, no damping)
  double rhoInf = 0.8;         ///< generalized_alpha: spectral radius at infinite frequency, [0, 1]
  double rtol = 1e-6;          ///< adaptive: relative tolerance
  double atol = 1e-8;          ///< adaptive: absolute tolerance (m, rad, m/s, rad/s alike)
  int maxOrder = 0;            ///< cvode_bdf (1-5), cvode_adams (1-12); 0: the method's maximum
  double maxStep = 0.0;        ///< adaptive: largest internal step, s (0: unbounded)
  double newtonTol = 1e-8;     ///< hht, generalized_alpha: Newton tolerance on the update of q, v (m, rad)
  int maxNewton = 8;           ///< hht, generalized_alpha: iterations before the Jacobian is refreshed
  LoopStabilization loops = LoopStabilization::Projection;
  double baumgarteAlpha = 0.0;  ///< 1/s, velocity feedback; 0: 0.2/dt
  double baumgarteBeta = 0.0;   ///< 1/s, position feedback; 0: 0.2/dt
};

inline constexpr double kUnconditionallyStable = std::numeric_limits<double>::infinity();

/// One integration method as the scene names it.
struct MethodInfo {
  std::string_view name;
  std::string_view summary;
  int order = 0;                ///< global order of accuracy (adaptive: maximum order)
  bool adaptive = false;        ///< step chosen by error control (SUNDIALS)
  bool implicit = false;        ///< solves a nonlinear system per step (Newton)
  bool indexThree = false;      ///< enforces g(q) = 0 with multipliers (no stabilisation needed)
  /// Largest omega*dt on the imaginary axis for which an undamped mode of frequency omega stays
  /// bounded (0: grows at any step; kUnconditionallyStable: any step). Adaptive methods control
  /// their own step: their value is kUnconditionallyStable, meaning "will not blow up", not "cheap".
  double imagStabilityLimit = 0.0;
};

/// Every method, in the order of the documentation.
std::span<const MethodInfo> integratorMethods();
/// (name) => its entry, or nullptr.
const MethodInfo* findMethod(std::string_view name);
/// The method names, for error messages and did-you-mean.
std::vector<std::string> integratorMethodNames();

/// A problem with a spec: the key (as in YAML: method, dt, alpha, rho_inf, ...) and what is wrong.
struct SpecProblem {
  std::string key;
  std::string message;
};
/// (spec) => every problem (unknown method, dt <= 0, alpha outside [-1/3, 0], ...); empty if fine.
std::vector<SpecProblem> checkIntegratorSpec(const IntegratorSpec& spec);

/// (spec, model) => the integrator; throws std::invalid_argument on the first problem of
/// checkIntegratorSpec. The model must outlive the integrator.
std::unique_ptr<Integrator> makeIntegrator(const IntegratorSpec& spec, const Model& model);

/// (spec, system) => the system projects after every step or adds Baumgarte terms, as the spec
/// says (index-3 methods ignore Baumgarte terms; projection then only corrects the velocities).
void configureLoopStabilization(const IntegratorSpec& spec, MultibodySystem& system);

}  // namespace yardsim::dynamics
