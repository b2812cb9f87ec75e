#pragma once
// Linear and quadratic damping per degree of freedom of one body, at a reference point and in the
// body's axes: F_i = -(b_i u_i + c_i |u_i| u_i) for u = (surge, sway, heave) velocity of the point
// and (roll, pitch, yaw) rates. A plain provider to tune a floating body (roll decay, heave
// settling) before radiation damping exists. Power F . u <= 0; no potential energy.
#include <array>
#include <string>

#include "forces/force_provider.hpp"

namespace yardsim::forces {

// Coefficients in the naval order surge, sway, heave (N s/m; N s^2/m^2), roll, pitch, yaw
// (N m s/rad; N m s^2/rad^2).
struct DampingCoefficients {
  std::array<double, 6> linear{};
  std::array<double, 6> quadratic{};
};

class LinearQuadraticDamping final : public ForceProvider {
 public:
  // (name, model, body >= 1, reference point p_B in the body frame, coefficients >= 0) => the
  // provider; throws std::invalid_argument naming it for a bad body, point or coefficient
  LinearQuadraticDamping(std::string name, const dynamics::Model& model, int body,
                         const dynamics::Vector3& p_B, const DampingCoefficients& c);

  int body() const { return body_; }
  // (stage) => the damping force and moment in the body axes (surge..yaw order), N and N m
  std::array<double, 6> load(const Stage& s) const;

 protected:
  void doEvaluate(const Stage& s, dynamics::ExternalForces& f, Eigen::VectorXd& tau) const override;
  double doPower(const Stage& s) const override;

 private:
  // (stage) => (surge, sway, heave) velocity of the point and (roll, pitch, yaw) rates, body axes
  std::array<double, 6> velocity(const Stage& s) const;

  int body_;
  dynamics::Vector3 p_B_;
  DampingCoefficients c_;
};

}  // namespace yardsim::forces
