#pragma once
// The frequency-domain counterpart of the time-domain Rankine solver on the same discrete system
// (the same panels, the same factorised mixed problem, the same damping zone): for a harmonic
// motion or wave, q(t) = Re(q^ e^{i w t}), the emp scheme's continuous-time limit
//   zeta_t = phi_z - 2 nu zeta + nu^2 phi / g,   phi_t = -g zeta
// gives on every free-surface panel phi_z = kappa phi with kappa = (w - i nu)^2 / g, and the mixed
// problem gives phi_z = -(G_fb a + G_ff p) (G = M^-1 [R_b R_f], the free-surface rows). So
//   (G_ff + diag kappa) p = -G_fb a
// one complex Nf x Nf solve per frequency, after which the hull potential is
// phi_b = G_bb a + G_bf p and the hull force F = rho int phi_t N dS = i w rho sum phi_b N A.
//   radiation, unit motion in mode j (a = i w N_j):  F_i = (w^2 A_ij - i w B_ij)
//   excitation, a unit-amplitude wave of heading b (eta = Re(e^{-i k x.e_b} e^{i w t})): the
//   Froude-Krylov force of the incident potential phi_I = i g/w f(z) e^{-i k x.e_b} and the
//   diffraction potential with a = -dphi_I/dn.
// It is the reference for the time-domain runs (same panels: they differ by the time stepping
// alone) and gives the response amplitude operators
//   RAO = X / (-w^2 (M + A) + i w B + C).
// Frames and units: the solver's (W axes at the mean pose, the water level at z = 0, moments about
// the body origin), naval order surge, sway, heave, roll, pitch, yaw; w rad/s, A kg, B kg/s, X N
// (N m) per m of wave amplitude, phases relative to the wave's crest at the world origin.
#include <complex>
#include <vector>

#include <Eigen/Core>

#include "forces/hydro/rankine_td_model.hpp"

namespace yardsim::forces::hydro {

struct FrequencyResponse {
  double omega = 0.0;                                                   ///< rad/s
  Eigen::Matrix<double, 6, 6> addedMass;                                ///< A(w), kg ...
  Eigen::Matrix<double, 6, 6> damping;                                  ///< B(w), kg/s ...
  std::vector<Eigen::Matrix<std::complex<double>, 6, 1>> excitation;    ///< X per heading, N/m
  std::vector<Eigen::Matrix<std::complex<double>, 6, 1>> froudeKrylov;  ///< its F-K part, N/m
};

/// The heavy part made once per panel model: G = M^-1 [R_b N, R_f] (N x 6 and N x Nf).
class FrequencyDomainSolver {
 public:
  explicit FrequencyDomainSolver(const RankineTdModel& model);
  /// (w > 0, headings in rad, the direction the waves travel towards, W axes) => A, B, X.
  /// Costs one complex LU of Nf x Nf. Throws std::invalid_argument for w <= 0.
  FrequencyResponse solve(double omega, const std::vector<double>& headings) const;

 private:
  const RankineTdModel& model_;
  Eigen::MatrixXd fromModes_;  ///< M^-1 R_b N, N x 6 (M^-1 R_b and M^-1 R_f: the model's
                               ///< solution map, read in place)
};

/// (rigid-body mass 6x6 M about the body origin, C the 6x6 restoring matrix, an added linear
/// damping D (viscous, N s/m ...; added to B), response, the heading's index, the modes kept free:
/// the others held) => the complex motion per m of wave amplitude in the free modes (the held
/// ones 0): m/m, rad/m.
Eigen::Matrix<std::complex<double>, 6, 1> responseAmplitude(
    const Eigen::Matrix<double, 6, 6>& mass, const Eigen::Matrix<double, 6, 6>& restoring,
    const Eigen::Matrix<double, 6, 6>& extraDamping, const FrequencyResponse& r,
    std::size_t heading, const std::vector<int>& freeModes);

}  // namespace yardsim::forces::hydro
