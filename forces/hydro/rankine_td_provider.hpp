#pragma once
// rankine_td: the radiation memory force of one floating body from the time-domain Rankine-panel
// solver, run at its own rate (a multiple of the mechanics step). Linear about the mean pose,
// zero forward speed, no incident wave (diffraction and the sea are the irregular-sea side's).
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
// Frames: the body's velocity (body frame [omega; v_O]) is taken to the mean pose's world axes
// with the mean rotation R_WB (linear theory), the force is returned in the body frame about the
// body origin. Units: s, m, N, N m.
//
// State (checkpointed through ProviderScratch::carried): the free-surface elevation and
// potential per panel, the time of the last panel step and the held force.
#include <memory>

#include "forces/force_provider.hpp"
#include "forces/hydro/emp_scheme.hpp"

namespace yardsim::forces::hydro {

class RankineTdProvider final : public ForceProvider {
 public:
  /// (name, multibody model, body >= 1, the panel model built at the body's mean pose, panel step
  /// in s) => the provider; throws std::invalid_argument naming it for a bad body or a panel step
  /// above the emp limit of the model's free surface (with the numbers).
  RankineTdProvider(std::string name, const dynamics::Model& model, int body,
                    std::shared_ptr<const RankineTdModel> panels, double panelStep);

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
  // (stage) => [v_O; omega] of the body in the mean pose's world axes
  Vector6 velocity_W(const Stage& s) const;

  int body_;
  std::shared_ptr<const RankineTdModel> panels_;
  double panelStep_;
};

}  // namespace yardsim::forces::hydro
