#pragma once
// The drag of a flow (wind on the hull and deck, current on the underwater hull) on one body,
// OCIMF style: with V the horizontal flow velocity relative to a reference point of the body
// and theta the angle the relative flow comes FROM in the body's heading axes (0: from ahead,
// along -x; 90 deg: from the +y side), in the heading axes
//   F_x = 1/2 rho V^2 A_frontal C_x(theta),  F_y = 1/2 rho V^2 A_lateral C_y(theta),
//   M_z = 1/2 rho V^2 A_lateral L C_mz(theta),
// signed coefficients of the force along +x, +y and the moment about +z. The forces act at the
// reference point, the yaw moment about the vertical. Not conservative: power F . v + M_z w_z.
// WindLoad and CurrentLoad (wind_load.hpp, current_load.hpp) say where the flow comes from.
#include <array>
#include <string>
#include <vector>

#include "forces/force_provider.hpp"

namespace yardsim::forces {

// Coefficients against the angle the relative flow comes from. A table from 0 to 180 deg is
// mirrored for port-starboard symmetry (C_x(-theta) = C_x(theta), C_y and C_mz change sign); a
// table from 0 to 360 deg is used as it is. Linear in between. The default (no table):
// C_x = -cos(theta), C_y = -sin(theta), C_mz = 0 (a drag coefficient of 1 in each direction).
class FlowCoefficients {
 public:
  FlowCoefficients() = default;
  // (angles, rad, strictly increasing from 0 to pi or 2 pi; cx, cy, cmz of the same size) =>
  // the table; throws std::invalid_argument saying what is wrong
  FlowCoefficients(std::vector<double> angles, std::vector<double> cx, std::vector<double> cy,
                   std::vector<double> cmz);
  // (theta, rad, any) => (C_x, C_y, C_mz)
  std::array<double, 3> at(double theta) const;

 private:
  std::vector<double> angles_, cx_, cy_, cmz_;  // empty: the default
  bool mirrored_ = false;
};

struct FlowAreas {
  double frontal = 0.0;  // m^2, projected on the body's y-z plane (flow along x)
  double lateral = 0.0;  // m^2, projected on the x-z plane (flow along y)
  double length =
      0.0;  // m, the length for the yaw moment (length overall or between perpendiculars)
};

// What a flow load did at the last evaluation (for recording).
struct FlowLoadState {
  dynamics::Vector3 force = dynamics::Vector3::Zero();  // N, world
  double yawMoment = 0.0;                               // N m about the vertical through the point
  double speed = 0.0;                                   // m/s, relative
  double angle = 0.0;                                   // rad, where the relative flow comes from
};

class FlowLoad : public ForceProvider {
 public:
  // (name, model, body >= 1, reference point p_B, areas >= 0, length >= 0, coefficients,
  // fluid density > 0) => the provider; throws std::invalid_argument naming it
  FlowLoad(std::string name, const dynamics::Model& model, int body, const dynamics::Vector3& p_B,
           const FlowAreas& areas, FlowCoefficients coefficients, double density);

  int body() const { return body_; }
  const dynamics::Vector3& point() const { return p_B_; }
  // (stage) => the load there
  FlowLoadState load(const Stage& s) const;

 protected:
  // (world point, t) => the flow velocity there, m/s
  virtual dynamics::Vector3 flowVelocity(const dynamics::Vector3& p_W, double t) const = 0;
  void doEvaluate(const Stage& s, dynamics::ExternalForces& f, Eigen::VectorXd& tau) const override;
  double doPower(const Stage& s) const override;

 private:
  int body_;
  dynamics::Vector3 p_B_;
  FlowAreas areas_;
  FlowCoefficients coefficients_;
  double density_;
};

}  // namespace yardsim::forces
