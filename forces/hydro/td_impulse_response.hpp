#pragma once
// The impulse responses of one floating hull computed by the time-domain Rankine solver itself
// (impulse_response.hpp says what they are and how the Cummins convolution uses them):
//
// Radiation: for each mode j an impulsive velocity xi_dot_j = delta(t) (discretely N_j / dt over
// the first step, so that zeta(0+) = dpsi_j/dz on the free surface), then the hull at rest;
//   K_ij(t_k) = -F^M_i(t_k),  k >= 1, and K_ij(0) = K_ij(0+) (zeta(0-) = 0, zeta(0+) from psi_j).
// Band limit: a free-surface mesh carries waves only up to the frequency whose wavelength spans
// several panels; the shorter waves an impulse also excites travel wrongly (at the mesh scale
// they hardly leave the hull) and ring in the raw K for the whole memory. So K is band-limited
// after the march, through its cosine transform (K is causal, so B fixes it):
//   B(w) = int_0^T K(t) cos(w t) dt,  K_band(t) = (2/pi) int_0^w2 B(w) taper(w) cos(w t) dw,
// taper = 1 below w1, a raised cosine from 1 at w1 to 0 at w2. Below w1 the damping is unchanged.
// The cut part of B also carried added mass below w1 (Kramers-Kronig: A(w) - A_inf =
// (2/pi) P int B(w') / (w'^2 - w^2) dw'), nearly constant there; so with a band limit the
// returned aInf is A_inf + dA, dA the mean over [w1/3, w1] of the difference of the sine
// transforms -(1/w) int K sin(w t) dt of the raw and the band-limited K, and the pair (aInf,
// K_band) gives the solver's A(w) and B(w) below w1 (tested against forced oscillation). Without
// a band limit aInf is A_inf from psi_j. resolvedFrequency() gives the w the mesh resolves.
// Excitation: for each heading beta a long-crested incident wave on the solver's depth h whose
// elevation at the body origin is a band-limited impulse,
//   eta(x, t) = (1/pi) int_0^inf W(w) cos(k xi - w t) dw,  xi = (x - x_O).e_beta, w^2 = g k tanh
//   kh, W(w) = exp(-(w / w_c)^2)  (so eta(x_O, t) = w_c / (2 sqrt(pi)) exp(-(w_c t / 2)^2), unit
//   area), phi_I = (1/pi) int W (g / w) cosh k(z + h) / cosh kh sin(k xi - w t) dw
// (incident_kinematics.hpp; until 2026-11-25 it was the deep-water wave on every depth, which in
// 20 m of water made a 60 s wave's slope 6.7 times too small: docs/hydrodynamics.md),
// the diffraction potential marched with the hull condition dphi_D/dn = -dphi_I/dn and
// F_exc = rho int (dphi_I/dt + dphi_D/dt) N dS (Froude-Krylov + diffraction). The response is
// that of the window: its transfer function is X(w) W(w), so w_c must lie above the sea's
// frequencies (X(w) = H(w) / W(w) recovers the excitation below about 2 w_c). The integral over w
// is the trapezoidal rule on [0, 3 w_c].
//
// Frames: the returned matrices and vectors are in body axes B about the body origin, naval
// order (impulse_response.hpp); the computation runs in world axes at the mean pose. Units: s,
// rad/s, N, m; K in N/(m s) (N m/(rad s) ...), h in N/(m s) per metre of elevation.
#include <vector>

#include "forces/hydro/impulse_response.hpp"
#include "forces/hydro/rankine_td_model.hpp"

namespace yardsim::forces::hydro {

struct ImpulseResponseSettings {
  RankineTdSettings solver;
  double dt = 0.0;               ///< s, the march's step and the responses' sample spacing
  double memory = 60.0;          ///< s, length of K(t) and of h(t) after t = 0
  std::vector<double> headings;  ///< rad, in B; empty: no excitation responses
  double cutoff = 0.0;           ///< w_c, rad/s (> 0 when there are headings)
  double lead = 0.0;       ///< s, how long before t = 0 the excitation march starts (0: 12 / w_c)
  int frequencies = 240;   ///< quadrature points on [0, 3 w_c]
  double bandStart = 0.0;  ///< w1, rad/s: K's damping kept below (0: raw K, no band limit)
  double bandEnd = 0.0;    ///< w2 > w1, rad/s: and tapered to 0 here
  /// true: the excitation is Froude-Krylov + diffraction; false: diffraction only (for a body
  /// whose hydrostatics already integrates the incident pressure)
  bool froudeKrylov = true;
};

/// (model, panels per wavelength) => the frequency of the deep-water wave whose length is that
/// many times the largest free-surface panel diameter outside the damping zone, rad/s.
double resolvedFrequency(const RankineTdModel& model, double panelsPerWave = 10.0);

/// (model, settings) => K(t) and h_beta(t) with aInf, headings, dt and excitationStart; the key is
/// left empty (the model does not keep the hull it was made from). Throws std::invalid_argument
/// with the numbers when dt exceeds the emp limit of the model's free-surface mesh.
ImpulseResponse computeImpulseResponse(const RankineTdModel& model,
                                       const ImpulseResponseSettings& settings);

/// (hull in B, mean pose X_WB, settings) => the same, building the model, with the key
/// impulseResponseKey(hull_B, X_WB, settings).
ImpulseResponse computeImpulseResponse(const PanelMesh& hull_B, const dynamics::Transform& X_WB,
                                       const ImpulseResponseSettings& settings);

/// (hull in B, X_WB, settings) => "rankine_td-" + 16 hex digits: FNV-1a (64 bit) over the mesh's
/// vertices and panels, the pose and every setting, so a cache can tell two hulls or two set-ups
/// apart (the same inputs always give the same key).
std::string impulseResponseKey(const PanelMesh& hull_B, const dynamics::Transform& X_WB,
                               const ImpulseResponseSettings& settings);

}  // namespace yardsim::forces::hydro
