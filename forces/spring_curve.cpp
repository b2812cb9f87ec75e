#include "forces/spring_curve.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace yardsim::forces {

SpringCurve SpringCurve::linear(double k) {
  if (!(std::isfinite(k) && k >= 0.0))
    throw std::invalid_argument("spring: the stiffness must be finite and >= 0 (got " +
                                std::to_string(k) + ")");
  SpringCurve c;
  c.k_ = k;
  return c;
}

SpringCurve SpringCurve::table(std::vector<double> x, std::vector<double> f,
                               const std::string& owner) {
  // (x, f) => checked; cumulative trapezoid integrals (exact for piecewise-linear f)
  if (x.size() < 2 || x.size() != f.size())
    throw std::invalid_argument("spring '" + owner +
                                "': a force table needs at least two (deflection, force) points");
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i]) || !std::isfinite(f[i]))
      throw std::invalid_argument("spring '" + owner + "': table point " + std::to_string(i) +
                                  " is not finite");
    if (i > 0 && !(x[i] > x[i - 1]))
      throw std::invalid_argument("spring '" + owner +
                                  "': table deflections must be strictly increasing (point " +
                                  std::to_string(i) + ")");
  }
  SpringCurve c;
  c.x_ = std::move(x);
  c.f_ = std::move(f);
  c.energyAt_.assign(c.x_.size(), 0.0);
  for (std::size_t i = 1; i < c.x_.size(); ++i)
    c.energyAt_[i] = c.energyAt_[i - 1] + 0.5 * (c.f_[i] + c.f_[i - 1]) * (c.x_[i] - c.x_[i - 1]);
  c.energyAtZero_ = 0.0;
  c.energyAtZero_ = c.energy(0.0);  // the integral from x_0 to 0, with energyAtZero_ still 0
  return c;
}

std::size_t SpringCurve::segment(double x) const {
  // (x) => i with x_i <= x < x_(i+1), clamped to the first and last segments
  const auto it = std::upper_bound(x_.begin() + 1, x_.end() - 1, x);
  return static_cast<std::size_t>(it - x_.begin()) - 1;
}

double SpringCurve::force(double x) const {
  if (x_.empty()) return k_ * x;
  const std::size_t i = segment(x);
  return f_[i] + stiffness(x) * (x - x_[i]);
}

double SpringCurve::stiffness(double x) const {
  if (x_.empty()) return k_;
  const std::size_t i = segment(x);
  return (f_[i + 1] - f_[i]) / (x_[i + 1] - x_[i]);
}

double SpringCurve::energy(double x) const {
  if (x_.empty()) return 0.5 * k_ * x * x;
  // (x) => integral from x_i to x of the linear f on segment i, plus the knots' sum, minus V(0)
  const std::size_t i = segment(x);
  const double dx = x - x_[i];
  return energyAt_[i] + dx * (f_[i] + 0.5 * stiffness(x) * dx) - energyAtZero_;
}

}  // namespace yardsim::forces
