#pragma once
// Explicit (forward) Euler: q = q (+) h v, v += h a(t, q, v), both from the state at the start of
// the step. First order; grows every undamped mode at any step (a reference, not a workhorse).

#include "dynamics/integrators/integrator.hpp"
#include "dynamics/model.hpp"

namespace yardsim::dynamics {

class ExplicitEuler final : public Integrator {
 public:
  explicit ExplicitEuler(const Model& model);
  void step(AccelerationSource& system, double& t, Eigen::VectorXd& q, Eigen::VectorXd& v, double h) override;
  std::string_view name() const override { return "explicit_euler"; }

 private:
  const Model& model_;
  Eigen::VectorXd a_;
};

}  // namespace yardsim::dynamics
