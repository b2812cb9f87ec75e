#pragma once
// Closed-loop mechanisms shared by the loop tests: a planar four-bar and a slider-crank, both in
// the x-y plane with revolute joints about z and gravity along -y, closed by a revolute cut
// (kAxisConstraint: its out-of-plane rows are redundant, which the Schur solve must tolerate).

#include <cmath>

#include "dynamics/model_builder.hpp"

namespace yardsim::dynamics::testing {

struct FourBar {
  double a, b, c, g;  ///< crank, coupler, rocker, ground lengths
  Model model;
  /// The closed configuration for crank angle theta (upper branch), by circle intersection.
  Eigen::VectorXd closedConfiguration(double theta) const {
    const Eigen::Vector2d E(a * std::cos(theta), a * std::sin(theta)), G(g, 0.0);
    const Eigen::Vector2d dEG = G - E;
    const double dist = dEG.norm();
    const double x = (b * b - c * c + dist * dist) / (2 * dist);
    const double y = std::sqrt(b * b - x * x);
    const Eigen::Vector2d ex = dEG / dist, ey(-ex.y(), ex.x());
    const Eigen::Vector2d P = E + x * ex + y * ey;
    Eigen::VectorXd q(3);
    q << theta, std::atan2(P.y() - E.y(), P.x() - E.x()) - theta, std::atan2(P.y() - G.y(), P.x() - G.x());
    return q;
  }
};

inline FourBar makeFourBar(double a, double b, double c, double g, std::uint8_t mask = kAxisConstraint) {
  ModelBuilder mb;
  mb.setGravity(Vector3(0, -9.81, 0));
  mb.addBody("crank", "world", Joint::revolute(), {}, rodInertia(1.0, a));
  mb.addBody("coupler", "crank", Joint::revolute(), Transform::translation(Vector3(a, 0, 0)), rodInertia(1.0, b));
  mb.addBody("rocker", "world", Joint::revolute(), Transform::translation(Vector3(g, 0, 0)), rodInertia(1.0, c));
  mb.addLoop("coupler-rocker", "coupler", Transform::translation(Vector3(b, 0, 0)), "rocker",
             Transform::translation(Vector3(c, 0, 0)), mask);
  return {a, b, c, g, mb.build()};
}

struct SliderCrank {
  double r, l;
  Model model;
  double sliderPosition(double theta) const {
    const double s = r * std::sin(theta);
    return r * std::cos(theta) + std::sqrt(l * l - s * s);
  }
  Eigen::VectorXd closedConfiguration(double theta) const {
    const double s = r * std::sin(theta);
    Eigen::VectorXd q(3);
    q << theta, -std::asin(s / l) - theta, sliderPosition(theta);
    return q;
  }
};

inline SliderCrank makeSliderCrank(double r, double l) {
  ModelBuilder mb;
  mb.setGravity(Vector3(0, -9.81, 0));
  mb.addBody("crank", "world", Joint::revolute(), {}, rodInertia(2.0, r));
  mb.addBody("rod", "crank", Joint::revolute(), Transform::translation(Vector3(r, 0, 0)), rodInertia(1.0, l));
  mb.addBody("slider", "world", Joint::prismatic(Vector3::UnitX()), {}, boxInertia(3.0, Vector3(0.2, 0.1, 0.1)));
  mb.addLoop("rod-slider", "rod", Transform::translation(Vector3(l, 0, 0)), "slider", {}, kAxisConstraint);
  return {r, l, mb.build()};
}

}  // namespace yardsim::dynamics::testing
