#pragma once
// The multibody state (q with quaternions, v) as a flat vector y = [theta; v] of size 2 nv for
// solvers that need one (SUNDIALS): theta is the chart coordinate around an origin q*, so that
// q = q* (+) theta (joints' integrate) always has unit quaternions, and
// dy/dt = [chartRate(theta, v); a(t, q, v)]. Re-gather (a new origin) before the chart's rotation
// grows large: rotationExtent() tells how far it has gone.

#include <Eigen/Core>

#include "dynamics/model.hpp"

namespace yardsim::dynamics {

class ChartState {
 public:
  explicit ChartState(const Model& model);
  int size() const { return 2 * model_.nv; }
  /// (q, v) => origin q* = q, y = [0; v]
  void gather(const Eigen::VectorXd& q, const Eigen::VectorXd& v, double* y);
  /// (y) => q = q* (+) theta, v
  void scatter(const double* y, Eigen::VectorXd& q, Eigen::VectorXd& v) const;
  /// (y, a) => the kinematic half of dy/dt: chartRate(theta, v) in ydot[0, nv)
  void kinematicRate(const double* y, double* ydot) const;
  /// (a) => the dynamic half of dy/dt: a in ydot[nv, 2 nv)
  void dynamicRate(const Eigen::VectorXd& a, double* ydot) const;
  /// (y) => largest rotation angle of a spherical or free joint in the chart, rad
  double rotationExtent(const double* y) const;
  const Eigen::VectorXd& origin() const { return origin_; }

 private:
  const Model& model_;
  Eigen::VectorXd origin_;
  mutable Eigen::VectorXd theta_, v_, rate_;
};

}  // namespace yardsim::dynamics
