#pragma once
// Response amplitude operators measured in the time domain: a floating hull on a chain of joints
// (the free modes among surge, sway, heave, roll, pitch, yaw: prismatic x, y, z, then revolute x,
// y, z, all through the body origin), with a linear restoring matrix C and the `rankine_td`
// provider (radiation + diffraction + Froude-Krylov of the sea, A_inf on the left-hand side) and an
// optional linear damping D (a viscous roll damping: it lets a lightly damped mode's transient
// die), run by RK4 from rest in one regular wave of amplitude a, frequency w, heading b; the steady
// motion of each free mode is fitted over the last whole periods by least squares to
//   xi(t) = c0 + c1 t + Re(xi^ e^{i w t})
// (the trend takes up the drift of a mode without restoring, such as sway), and the RAO is
// xi^ / a (phase against the wave crest at the world origin, as frequency_domain.hpp).
// Units and frames: the hull in its body frame, the mean pose at the world origin (identity),
// mass and C as 6x6 about the body origin in naval order (kg, kg m, kg m^2; N/m, N m/rad ...),
// s, rad/s, m.
#include <complex>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "forces/hydro/rankine_td_model.hpp"

namespace yardsim::forces::hydro {

struct RegularWaveRun {
  double omega = 1.0;      ///< rad/s
  double heading = 0.0;    ///< rad, direction the wave travels towards (from +x towards +y)
  double amplitude = 0.1;  ///< m
  double step =
      0.0;  ///< s, RK4 step (the panel step is the same); 0: T/40 or 0.45 of the emp limit
  int rampPeriods = 4;            ///< the sea's ramp
  int periods = 20;               ///< total
  int analysisPeriods = 6;        ///< the last ones
  std::vector<int> freeModes{2};  ///< naval indices 0..5, increasing
  /// linear damping D about the body origin, naval order (N s/m, N m s/rad ...): -D xi_dot
  Eigen::Matrix<double, 6, 6> damping = Eigen::Matrix<double, 6, 6>::Zero();
};

/// A rigid body: mass (kg), centre of mass (body frame, m), inertia about it (kg m^2).
struct RigidBody {
  double mass = 0.0;
  Vector3 com = Vector3::Zero();
  Eigen::Matrix3d inertiaCom = Eigen::Matrix3d::Zero();
};

/// (body) => its 6x6 mass about the body origin in naval order [force; moment] x [linear; angular].
Eigen::Matrix<double, 6, 6> rigidBodyMass(const RigidBody& body);

/// (panel model of the hull at the identity pose, body, C, run) => RAO per mode (0 for held
/// ones). Throws std::invalid_argument for bad modes or run settings.
Eigen::Matrix<std::complex<double>, 6, 1> measuredResponse(
    std::shared_ptr<const RankineTdModel> panels, const RigidBody& body,
    const Eigen::Matrix<double, 6, 6>& restoring, const RegularWaveRun& run);

}  // namespace yardsim::forces::hydro
