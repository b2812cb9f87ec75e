#pragma once
// The impulse responses of one floating hull, as the time-domain Rankine solver computes them
// (an impulsive motion per mode, an impulsive incident wave per heading) and as the Cummins
// convolution consumes them. Linear about the mean wetted surface, zero forward speed.
//
// Frames and order: body frame B of the hull at its mean pose, about the body origin; rows and
// columns surge, sway, heave, roll, pitch, yaw (translations first, naval order, as addedMass()).
// Units: force rows N, moment rows N m; translation columns m, rotation columns rad.
//
// Radiation (Cummins 1962), for body velocities xi_dot(t) in B about the origin:
//   F_rad(t) = -aInf xi_ddot(t) - int_0^t K(t - tau) xi_dot(tau) dtau,
//   K_ij(t_k) = radiation[k](i, j), t_k = k dt, k = 0 .. radiation.size() - 1 (memory length).
// Excitation (diffraction + Froude-Krylov, or diffraction only: froudeKrylov), for the incident
// elevation eta(t) at the body origin of a long-crested wave travelling towards heading beta (rad,
// from +x towards +y in B):
//   F_exc(t) = int h_beta(tau) eta(t - tau) dtau,  h_beta(t0 + k dt) = excitation[b][k],
// non-causal (t0 < 0).
#include <string>
#include <vector>

#include <Eigen/Core>

namespace yardsim::forces::hydro {

struct ImpulseResponse {
  using Matrix6 = Eigen::Matrix<double, 6, 6>;
  using Vector6 = Eigen::Matrix<double, 6, 1>;

  double dt = 0.0;                 ///< s, sample spacing of every response
  Matrix6 aInf = Matrix6::Zero();  ///< infinite-frequency added mass (kg, kg m, kg m^2)
  std::vector<Matrix6> radiation;  ///< K(t_k), N/(m s) (per unit velocity and time)
  std::vector<double> headings;    ///< rad, one per excitation response
  double excitationStart = 0.0;    ///< t0 of excitation[b][0], s (<= 0)
  /// w_c, rad/s, of the window W(w) = exp(-(w / w_c)^2) the excitation responses carry (their
  /// transfer function is X(w) W(w); ImpulseResponseForce divides W out); 0: no window
  double excitationWindow = 0.0;
  std::vector<std::vector<Vector6>> excitation;  ///< h_beta(t0 + k dt), N/(m s) per unit elevation
  /// true: the excitation responses hold Froude-Krylov + diffraction (the interface's meaning);
  /// false: diffraction only (for a hull whose hydrostatics integrates the incident pressure)
  bool froudeKrylov = true;
  std::string key;  ///< hash of the mesh and the settings that made it
};

}  // namespace yardsim::forces::hydro
