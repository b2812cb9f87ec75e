#pragma once
// Adams-Bashforth of order 2, 3 or 4 at a fixed step, started by RK4. Each step works in the
// chart centred on the current configuration q_n: the earlier points are brought into it with
// difference() and their chart rates, so the method keeps its order with quaternion joints.
// One acceleration evaluation per step. The history is kept only while steps follow each other
// with the same h from the state the previous step returned; otherwise the method restarts.

#include <array>

#include "dynamics/integrators/integrator.hpp"
#include "dynamics/integrators/rk4.hpp"
#include "dynamics/model.hpp"

namespace yardsim::dynamics {

class AdamsBashforth final : public Integrator {
 public:
  /// order in {2, 3, 4}
  AdamsBashforth(const Model& model, int order);
  void step(AccelerationSource& system, double& t, Eigen::VectorXd& q, Eigen::VectorXd& v, double h) override;
  std::string_view name() const override;
  void reset() override { count_ = 0; }
  bool carriesHistory() const override { return true; }
  int order() const { return order_; }

 private:
  const Model& model_;
  int order_;
  Rk4 starter_;
  int count_ = 0;  // valid history entries
  int head_ = 0;   // slot of the newest entry
  std::array<Eigen::VectorXd, 4> qh_, vh_, ah_;  // history ring: configuration, velocity, acceleration
  Eigen::VectorXd theta_, rate_, sumTheta_, sumA_;
  double tLast_ = 0.0, hLast_ = 0.0;
  Eigen::VectorXd qLast_, vLast_;
};

}  // namespace yardsim::dynamics
