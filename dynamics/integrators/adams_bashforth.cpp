#include "dynamics/integrators/adams_bashforth.hpp"

#include <cmath>
#include <stdexcept>

#include "dynamics/configuration.hpp"

namespace yardsim::dynamics {

namespace {
// b_j of y_{n+1} = y_n + h sum_j b_j f_{n-j}, per order
constexpr double kCoefficients[5][4] = {
    {0, 0, 0, 0},
    {1, 0, 0, 0},
    {1.5, -0.5, 0, 0},
    {23.0 / 12, -16.0 / 12, 5.0 / 12, 0},
    {55.0 / 24, -59.0 / 24, 37.0 / 24, -9.0 / 24},
};
}  // namespace

AdamsBashforth::AdamsBashforth(const Model& model, int order)
    : model_(model),
      order_(order),
      starter_(model),
      theta_(model.nv),
      rate_(model.nv),
      sumTheta_(model.nv),
      sumA_(model.nv),
      qLast_(model.nq),
      vLast_(model.nv) {
  if (order < 2 || order > 4) throw std::invalid_argument("Adams-Bashforth: order must be 2, 3 or 4");
  for (int k = 0; k < 4; ++k) {
    qh_[k].resize(model.nq);
    vh_[k].resize(model.nv);
    ah_[k].resize(model.nv);
  }
}

std::string_view AdamsBashforth::name() const {
  static constexpr std::string_view kNames[3] = {"ab2", "ab3", "ab4"};
  return kNames[order_ - 2];
}

void AdamsBashforth::step(AccelerationSource& system, double& t, Eigen::VectorXd& q, Eigen::VectorXd& v, double h) {
  // (t, q, v, h) => keep the history only if this step continues the previous one
  const double tol = 1e-9 * std::max(1.0, std::abs(t));
  if (count_ > 0 && (std::abs(t - tLast_) > tol || std::abs(h - hLast_) > 1e-9 * std::abs(h) || q != qLast_ ||
                     v != vLast_))
    count_ = 0;
  // (t, q, v) => newest history entry (q_n, v_n, a_n)
  head_ = (head_ + 1) % 4;
  qh_[head_] = q;
  vh_[head_] = v;
  evaluate(system, t, q, v, ah_[head_]);
  count_ = std::min(count_ + 1, order_);
  if (count_ < order_) {
    // (too little history) => one RK4 step
    starter_.step(system, t, q, v, h);
    stats_.f_evals += 4;
  } else {
    // (history in the chart at q_n) => theta = h sum b_j rate_j, v += h sum b_j a_j
    const double* b = kCoefficients[order_];
    sumTheta_ = b[0] * vh_[head_];
    sumA_ = b[0] * ah_[head_];
    for (int j = 1; j < order_; ++j) {
      const int k = (head_ - j + 4) % 4;
      difference(model_, q, qh_[k], theta_);
      chartRate(model_, theta_, vh_[k], rate_);
      sumTheta_ += b[j] * rate_;
      sumA_ += b[j] * ah_[k];
    }
    integrate(model_, q, sumTheta_, h, q);
    v += h * sumA_;
    t += h;
    system.afterStep(t, q, v);
  }
  ++stats_.steps;
  tLast_ = t;
  hLast_ = h;
  qLast_ = q;
  vLast_ = v;
}

}  // namespace yardsim::dynamics
