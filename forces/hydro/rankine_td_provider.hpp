#pragma once
// rankine_td: the radiation memory force of one floating body from the time-domain Rankine-panel
// solver, run at its own rate (a multiple of the mechanics step), and with a sea the diffraction
// force of its incident waves (regular and irregular: every component of forces::AiryWaves).
// Linear about the mean pose, zero forward speed.
//
// Diffraction: the disturbance potential's hull condition gets -dphi_I/dn and its dphi^M/dt
// problem -d2phi_I/(dn dt) at the mean panel centroids (linear Airy kinematics on the sea's depth,
// unstretched, times the sea's ramp(t); the ramp's own rate is neglected, as on the
// impulse-response path), so the held force is radiation + diffraction. With froudeKrylov the
// incident pressure's force rho int dphi_I/dt N dS on the mean wetted surface is added as well;
// without it (the default in scenes) the hydrostatics provider's nonlinear Froude-Krylov force is
// the only one, as on the impulse-response path with `froude_krylov: 0`. Per panel step the
// incident terms cost 4 Nb Nc multiply-adds (Nb hull panels, Nc components; tables made once).
//
// Coupling (DESIGN.md, expensive providers): the body carries the infinite-frequency added mass
// on the left-hand side of the multibody equations (addedMass() below, set with
// ModelBuilder::setAddedMass through mechanics/added_mass_build, as today), so the provider adds
// only the memory force F^M = rho int dphi^M/dt N dS. Every panelStep seconds, at the first stage
// of the mechanics step that starts at or after the next panel time (stepStart: an accepted
// state), it takes the hull's normal velocity from that stage, advances the free surface by one
// emp step (emp_scheme.hpp) and holds the F^M it returns until the next panel time (zero-order
// hold). A step retried from the same start does not advance it again.
//
// Frames: the body's velocity (body frame [omega; v_O]) is taken to world axes (the panels' axes)
// with the body's rotation R_WB at the stage, and the force, computed in world axes on the mean
// wetted surface, is returned in the body frame about the body origin through the same R_WB: the
// force keeps its world direction while the body turns (linear theory; until 2026-11-25 both used
// the mean rotation, which turned a rolling body's heave force into a mean sway force, and a
// drifting body's sway velocity into heave and roll: the growing roll of docs/hydrodynamics.md).
// Units: s, m, N, N m.
//
// State (checkpointed through ProviderScratch::carried): the free-surface elevation and
// potential per panel, the time of the last panel step and the held force.
#include <memory>

#include "forces/airy_waves.hpp"
#include "forces/force_provider.hpp"
#include "forces/hydro/emp_scheme.hpp"

namespace yardsim::forces::hydro {

class RankineTdProvider final : public ForceProvider {
 public:
  /// (name, multibody model, body >= 1, the panel model built at the body's mean pose, panel step
  /// in s, the sea or nullptr (radiation only), Froude-Krylov included) => the provider; throws
  /// std::invalid_argument naming it for a bad body or a panel step above the emp limit of the
  /// model's free surface (with the numbers).
  RankineTdProvider(std::string name, const dynamics::Model& model, int body,
                    std::shared_ptr<const RankineTdModel> panels, double panelStep,
                    std::shared_ptr<const AiryWaves> sea = nullptr, bool froudeKrylov = false);

  int body() const { return body_; }
  double panelStep() const { return panelStep_; }
  const RankineTdModel& panels() const { return *panels_; }
  /// infinite-frequency added mass for the left-hand side: body axes about the body origin, naval
  /// order (addedMassAboutOrigin converts it for ModelBuilder::setAddedMass)
  Eigen::Matrix<double, 6, 6> addedMass() const {
    return toBodyAxes(panels_->aInf(), panels_->rotation());
  }

  std::unique_ptr<ProviderScratch> makeScratch() const override;

 protected:
  void doEvaluate(const Stage& s, dynamics::ExternalForces& f, Eigen::VectorXd& tau) const override;
  double doPower(const Stage& s) const override;

 private:
  // (stage, scratch) => the held memory force in W axes after advancing when a panel time is due
  const Vector6& memoryForce(const Stage& s, ProviderScratch& scratch) const;
  // (stage) => [v_O; omega] of the body in world axes
  Vector6 velocity_W(const Stage& s) const;

  int body_;
  std::shared_ptr<const RankineTdModel> panels_;
  double panelStep_;
  std::shared_ptr<const AiryWaves> sea_;
  // the incident wave at the hull centroids, per component i (columns) as
  // q(t) = ramp(t) (C.col(i) cos(w_i t) + S.col(i) sin(w_i t)) summed over i:
  // dphi_I/dn (Nb x Nc, m/s), d2phi_I/(dn dt) (Nb x Nc, m/s^2), the Froude-Krylov force (6 x Nc, N)
  Eigen::MatrixXd cN_, sN_, cNt_, sNt_, cF_, sF_;
  Eigen::VectorXd omega_;  // rad/s per component
};

}  // namespace yardsim::forces::hydro
