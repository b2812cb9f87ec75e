#pragma once
// The small interface between a second-order system on the configuration manifold and a
// fixed-step integrator. The state is (q, v); dq/dt follows v through the joints' integrate().

#include <Eigen/Core>
#include <string_view>

namespace yardsim::dynamics {

/// dv/dt = a(t, q, v), plus an optional hook after every accepted step (projection, events).
class AccelerationSource {
 public:
  virtual ~AccelerationSource() = default;
  /// (t, q, v) => a (size nv, preallocated by the caller).
  virtual void acceleration(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::VectorXd& a) = 0;
  /// Called with the new state after each step; may change it (e.g. constraint projection).
  virtual void afterStep(double /*t*/, Eigen::VectorXd& /*q*/, Eigen::VectorXd& /*v*/) {}
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  /// (t, q, v) => (t + h, q, v) after one step of size h. No allocation.
  virtual void step(AccelerationSource& system, double& t, Eigen::VectorXd& q, Eigen::VectorXd& v, double h) = 0;
  virtual std::string_view name() const = 0;
};

}  // namespace yardsim::dynamics
