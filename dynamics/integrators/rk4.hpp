#pragma once
// Classical fourth-order Runge-Kutta on the configuration manifold: each step integrates the
// chart coordinate theta (q = q0 (+) theta) and v as an ODE in R^(2 nv), so it keeps order 4
// for quaternion joints too.

#include "dynamics/integrators/integrator.hpp"
#include "dynamics/model.hpp"

namespace yardsim::dynamics {

class Rk4 final : public Integrator {
 public:
  explicit Rk4(const Model& model);
  void step(AccelerationSource& system, double& t, Eigen::VectorXd& q, Eigen::VectorXd& v, double h) override;
  std::string_view name() const override { return "rk4"; }

 private:
  const Model& model_;
  Eigen::VectorXd q0_, qs_, v0_, vs_, theta_, sumTheta_, sumA_, a_, kTheta_;
};

}  // namespace yardsim::dynamics
