#pragma once
// SUNDIALS ARKODE (ARKStep) on the multibody state (adaptive_integrator.hpp): arkode_erk, an
// explicit Runge-Kutta method of order 4 (non-stiff); arkode_dirk, a diagonally implicit RK method
// of order 4 with Newton on a dense Jacobian (stiff); arkode_imex, the additive ARK4(3)6L pair with
// the kinematic equation dtheta/dt = chartRate(theta, v) explicit and the dynamics dv/dt = a
// implicit. Tolerances rtol/atol, root finding.

#include "dynamics/integrators/adaptive_integrator.hpp"

namespace yardsim::dynamics {

class Arkode final : public AdaptiveIntegrator {
 public:
  enum class Kind { Erk, Dirk, Imex };
  /// spec.method is arkode_erk, arkode_dirk or arkode_imex.
  Arkode(const Model& model, const IntegratorSpec& spec);
  ~Arkode() override;
  std::string_view name() const override;

 private:
  void init(double t, int roots) override;
  int advance(double tout, double& tret) override;
  bool rootReturn(int flag) const override;
  void rootInfo(int* found) override;
  void counters(IntegratorStats& s) override;
  Kind kind_;
};

}  // namespace yardsim::dynamics
