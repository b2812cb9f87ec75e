#include "dynamics/integrators/rk4.hpp"

#include "dynamics/configuration.hpp"

namespace yardsim::dynamics {

Rk4::Rk4(const Model& model)
    : model_(model),
      q0_(model.nq),
      qs_(model.nq),
      v0_(model.nv),
      vs_(model.nv),
      theta_(model.nv),
      sumTheta_(model.nv),
      sumA_(model.nv),
      a_(model.nv),
      kTheta_(model.nv) {}

void Rk4::step(AccelerationSource& system, double& t, Eigen::VectorXd& q, Eigen::VectorXd& v, double h) {
  q0_ = q;
  v0_ = v;
  // stage 1: (t, q0, v0) => a1; theta rate = v0
  evaluate(system, t, q0_, v0_, a_);
  sumTheta_ = v0_;
  sumA_ = a_;
  static constexpr double kC[3] = {0.5, 0.5, 1.0};
  static constexpr double kW[3] = {2.0, 2.0, 1.0};
  for (int s = 0; s < 3; ++s) {
    // stage s+2: (theta = c h k_theta, v = v0 + c h a) => a, k_theta
    const double ch = kC[s] * h;
    if (model_.euclidean) {
      // (q0 (+) theta = q0 + theta, theta rate = v: configuration.cpp's Euclidean case) => the
      // same doubles without theta and k_theta (the previous stage's v is its theta rate)
      qs_ = q0_ + ch * (s == 0 ? v0_ : vs_);
      vs_ = v0_ + ch * a_;
      evaluate(system, t + ch, qs_, vs_, a_);
      sumTheta_ += kW[s] * vs_;
    } else {
      theta_ = ch * (s == 0 ? v0_ : kTheta_);
      integrate(model_, q0_, theta_, 1.0, qs_);
      vs_ = v0_ + ch * a_;
      evaluate(system, t + ch, qs_, vs_, a_);
      chartRate(model_, theta_, vs_, kTheta_);
      sumTheta_ += kW[s] * kTheta_;
    }
    sumA_ += kW[s] * a_;
  }
  // (sums) => q = q0 (+) h/6 sum theta rates, v = v0 + h/6 sum a
  if (model_.euclidean) {
    q = q0_ + (h / 6.0) * sumTheta_;
  } else {
    theta_ = (h / 6.0) * sumTheta_;
    integrate(model_, q0_, theta_, 1.0, q);
  }
  v = v0_ + (h / 6.0) * sumA_;
  t += h;
  ++stats_.steps;
  system.afterStep(t, q, v);
}

}  // namespace yardsim::dynamics
