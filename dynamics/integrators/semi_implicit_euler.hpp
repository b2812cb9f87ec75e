#pragma once
// Semi-implicit (symplectic) Euler: v += h a(t, q, v); q = q (+) h v. First order, cheap, and
// with bounded energy error for conservative systems.

#include "dynamics/integrators/integrator.hpp"
#include "dynamics/model.hpp"

namespace yardsim::dynamics {

class SemiImplicitEuler final : public Integrator {
 public:
  explicit SemiImplicitEuler(const Model& model);
  void step(AccelerationSource& system, double& t, Eigen::VectorXd& q, Eigen::VectorXd& v, double h) override;
  std::string_view name() const override { return "semi_implicit_euler"; }

 private:
  const Model& model_;
  Eigen::VectorXd a_;
};

}  // namespace yardsim::dynamics
