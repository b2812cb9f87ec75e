#pragma once
// SUNDIALS CVODE on the multibody state (adaptive_integrator.hpp): BDF (orders 1-5, for stiff
// scenes; max_order 2 keeps it A-stable) or Adams-Moulton (orders 1-12, non-stiff), both with
// Newton iterations on a dense difference-quotient Jacobian, tolerances rtol/atol, and root finding.

#include "dynamics/integrators/adaptive_integrator.hpp"

namespace yardsim::dynamics {

class Cvode final : public AdaptiveIntegrator {
 public:
  /// spec.method is cvode_bdf or cvode_adams.
  Cvode(const Model& model, const IntegratorSpec& spec);
  ~Cvode() override;
  std::string_view name() const override { return bdf_ ? "cvode_bdf" : "cvode_adams"; }

 private:
  void init(double t, int roots) override;
  int advance(double tout, double& tret) override;
  bool rootReturn(int flag) const override;
  void rootInfo(int* found) override;
  void counters(IntegratorStats& s) override;
  bool bdf_;
};

}  // namespace yardsim::dynamics
