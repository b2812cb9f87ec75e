#pragma once
// The elastic law of a spring: the force (or moment) as a function of the deflection, linear
// (f = k x) or a piecewise-linear table through (x_i, f_i) extended linearly beyond its ends with
// the slopes of its end segments, and its exact strain energy V(x) = integral_0^x f. Shared by the
// translational and the rotational spring-damper. Units: x in m (rad) and f in N (N m) for a
// translational (rotational) spring.
#include <string>
#include <vector>

namespace yardsim::forces {

class SpringCurve {
 public:
  // (k >= 0, N/m or N m/rad) => f = k x; throws std::invalid_argument for a negative or
  // non-finite k
  static SpringCurve linear(double k);
  // (points (x_i, f_i) with x strictly increasing, at least two, owner for messages) => the
  // table; throws std::invalid_argument naming the owner for fewer than two points, x not
  // strictly increasing or a non-finite value. f(0) need not be 0: a table may carry its own
  // preload.
  static SpringCurve table(std::vector<double> x, std::vector<double> f,
                           const std::string& owner = "spring");

  // (x) => f(x)
  double force(double x) const;
  // (x) => df/dx at x (the slope of the segment holding x), N/m or N m/rad
  double stiffness(double x) const;
  // (x) => V(x) = integral from 0 to x of f, J (exact for the piecewise-linear table)
  double energy(double x) const;

 private:
  // (x) => index i of the segment [x_i, x_(i+1)] holding x (the end segments extend outward)
  std::size_t segment(double x) const;

  double k_ = 0.0;                // a linear spring when x_ is empty
  std::vector<double> x_, f_;     // the table
  std::vector<double> energyAt_;  // integral from x_0 to x_i of f
  double energyAtZero_ = 0.0;     // integral from x_0 to 0 of f
};

}  // namespace yardsim::forces
