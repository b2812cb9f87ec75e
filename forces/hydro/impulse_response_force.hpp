#pragma once
// The hydrodynamic force of the impulse-response path on one floating body (docs/hydrodynamics.md,
// "The Cummins convolution"): radiation memory and wave excitation from the impulse responses of
// its hull (forces/hydro/impulse_response.hpp), a force provider evaluated at every stage.
//   F = -int_0^t K(t - tau) xi_dot(tau) dtau + F_exc(t), body frame B, about the body origin,
// xi_dot the body's velocity [v; omega] in B (naval order). The infinite-frequency added mass
// aInf is not applied here: it belongs on the left-hand side (the body's added mass), as the
// scene wiring puts it.
// Excitation: for every regular component of the sea (forces::AiryWaves) the response's transfer
// function H(w, b) = int h_b(tau) e^{i w tau} dtau at its frequency, for the component's heading
// relative to the body's yaw (linear between the response's headings, periodic), at the body
// origin's horizontal position: F_exc = ramp(t) sum a Re(H e^{i theta}), theta the component's
// phase there. This equals the convolution of h with the incident elevation, without sampling it.
// The Froude-Krylov part of h is also in the hydrostatics provider's pressure in waves: see
// docs/hydrodynamics.md before combining the two on one body.
// State: the velocity history (RadiationMemory) lives in the scratch; committed states are those
// of a stage at its step's start (Stage::stepStart == t), or else the latest stage before a new
// step's start; it is carried into checkpoints. Allocation-free given its scratch.
#include <complex>
#include <memory>
#include <string>
#include <vector>

#include "forces/airy_waves.hpp"
#include "forces/force_provider.hpp"
#include "forces/hydro/impulse_response.hpp"
#include "forces/hydro/radiation_memory.hpp"

namespace yardsim::forces::hydro {

/// (response, the sea) => a problem per sea component above the response's resolved frequency,
/// its excitation window's cutoff w_c (a response computed with the default cutoff has w_c = the
/// frequency its free-surface mesh resolves; a cutoff set by hand claims that much): above w_c
/// the recorded excitation is the window's tail, and dividing W(w) out amplifies its error
/// (e^1 at w_c, e^4 at 2 w_c, where the force itself refuses). None for a response without window.
std::vector<std::string> checkResolvedSea(const ImpulseResponse& response, const AiryWaves& sea);

class ImpulseResponseForce final : public ForceProvider {
 public:
  // (name, model, body, response, sea or nullptr: no excitation) => the provider; throws
  // std::invalid_argument for the world or a body outside the model, a bad response, or a sea
  // with waves and a response without excitation
  ImpulseResponseForce(std::string name, const dynamics::Model& model, int body,
                       std::shared_ptr<const ImpulseResponse> response,
                       std::shared_ptr<const AiryWaves> sea);

  int body() const { return body_; }
  const ImpulseResponse& response() const { return *response_; }
  std::unique_ptr<ProviderScratch> makeScratch() const override;

  // (stage) => -mu(t): the radiation memory force, naval order in B (N, N m)
  Vector6 radiation(const Stage& s) const;
  // (stage) => the wave excitation, naval order in B (N, N m)
  Vector6 excitation(const Stage& s) const;

 protected:
  void doEvaluate(const Stage& s, dynamics::ExternalForces& f, Eigen::VectorXd& tau) const override;
  double doPower(const Stage& s) const override;

 private:
  struct Scratch;
  // (stage) => the velocity, the scratch with the committed history up to date
  Scratch& prepared(const Stage& s, std::unique_ptr<ProviderScratch>& temporary, Vector6& xi) const;

  int body_;
  std::shared_ptr<const ImpulseResponse> response_;
  std::shared_ptr<const AiryWaves> sea_;
  RetardationKernel kernel_;
  std::vector<std::size_t> order_;  // headings sorted
  // per sea component, per sorted heading: H(w_i, b)
  std::vector<std::complex<double>> transfer_;  // [component][heading][row], 6 per heading
};

}  // namespace yardsim::forces::hydro
