#pragma once
// The one interface of every force provider (gravity, wire ropes, equalizers, body loads,
// hydrostatics, contact, ...). A provider is evaluated inside every integrator stage (tight
// coupling, DESIGN.md): it reads the stage's state and kinematics and adds spatial forces on
// bodies and generalized joint forces. evaluate() is the checked, non-virtual entry point: it
// calls the protected doEvaluate() and refuses non-finite results with a ForceError naming the
// provider, the body and the time. Each provider also reports the potential energy it stores
// and the power of its non-conservative part, so that a scene's energy balance
//   kinetic + sum(potential) - integral(sum(power)) dt = constant
// can be checked.
//
// Providers are immutable while a system runs: evaluate(), potentialEnergy() and power() are
// const. What a provider writes while it computes (a rope's path points, a clipped hull) lives
// in a ProviderScratch it makes once (makeScratch()) and the caller owns: mechanics::Data holds
// one per provider of a system and hands it over in Stage::scratch. A caller that gives none
// (a test, a one-off evaluation) gets a temporary one, made, used and dropped in that call.
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dynamics/data.hpp"
#include "dynamics/external_forces.hpp"
#include "dynamics/model.hpp"

namespace yardsim::forces {

class Winch;

// A provider's scratch: what it writes while it is evaluated. Owned by the caller.
class ProviderScratch {
 public:
  virtual ~ProviderScratch() = default;
  // What of the scratch carries over from one stage to the next and changes results (a Newton
  // solve's warm start), for checkpoints: () => its values appended to out; (values that
  // carried() gave) => restored. Default: nothing carries over.
  virtual void carried(std::vector<double>& /*out*/) const {}
  virtual void restoreCarried(std::span<const double> /*values*/) {}
};

// What a provider sees at one integrator stage: data holds forwardKinematics(q, v) (X_WB, V).
struct Stage {
  double t;  // s
  const dynamics::Model& model;
  const dynamics::Data& data;
  const Eigen::VectorXd& q;
  const Eigen::VectorXd& v;
  // this provider's scratch (from its makeScratch()); nullptr: a temporary one is made
  ProviderScratch* scratch = nullptr;
  // s: the start of the integrator step in progress (a load read at the step's end takes its
  // value before a jump there, forces/body_load.hpp); infinity outside a step
  double stepStart = std::numeric_limits<double>::infinity();
};

// A provider produced a non-finite force, or was given a state it cannot handle.
class ForceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// (model, spatial forces f on its bodies, joint forces tau) => every coefficient is finite
bool forcesFinite(const dynamics::Model& model, const dynamics::ExternalForces& f,
                  const Eigen::VectorXd& tau);

class ForceProvider {
 public:
  explicit ForceProvider(std::string name) : name_(std::move(name)) {}
  virtual ~ForceProvider() = default;
  ForceProvider(const ForceProvider&) = delete;
  ForceProvider& operator=(const ForceProvider&) = delete;

  const std::string& name() const { return name_; }

  // () => a scratch sized for this provider, or nullptr when it writes nothing
  virtual std::unique_ptr<ProviderScratch> makeScratch() const { return nullptr; }

  // (stage) => forces added to f and generalized forces added to tau (size nv); throws
  // ForceError when what this provider added is not finite. Allocation-free given a scratch.
  void evaluate(const Stage& s, dynamics::ExternalForces& f, Eigen::VectorXd& tau) const;
  // (stage) => the same forces as evaluate(), added without the check: for a caller that adds
  // several providers' forces, checks their sum once (forcesFinite) and, when it is not finite,
  // evaluates them again through evaluate() to name the provider (mechanics/stage.cpp)
  void evaluateUnchecked(const Stage& s, dynamics::ExternalForces& f, Eigen::VectorXd& tau) const {
    doEvaluate(s, f, tau);
  }
  // (stage) => energy stored by this provider, J (gravity: m g h; a rope: its strain energy)
  double potentialEnergy(const Stage& s) const { return doPotentialEnergy(s); }
  // (stage) => power of the non-conservative part into the system, W (damping <= 0; a winch
  // paying out or hauling in: the rate of change of stored energy it causes)
  double power(const Stage& s) const { return doPower(s); }
  // Whether the provider's law has branches a step can switch between (a contact closing or
  // opening); false by default. The implicit integrators then compare regime() at a step's start
  // and end and sub-step a step that switched (docs/integrators.md "Switching forces").
  virtual bool switches() const { return false; }
  // (stage) => a signature of the branches in force at the stage (equal: the same branches)
  std::uint64_t regime(const Stage& s) const { return doRegime(s); }
  // () => the winch that sets this provider's unstretched length (a crane rope with mass), which
  // takes payout set-points between steps (never during one); null by default. The massless
  // ropes' winches are forces::Rope::winch().
  virtual Winch* payoutWinch() { return nullptr; }

 protected:
  virtual void doEvaluate(const Stage& s, dynamics::ExternalForces& f,
                          Eigen::VectorXd& tau) const = 0;
  // (stage, a temporary for callers that gave no scratch) => the stage's scratch as T
  template <class T>
  T& scratchOf(const Stage& s, std::unique_ptr<ProviderScratch>& temporary) const {
    if (s.scratch != nullptr) return static_cast<T&>(*s.scratch);
    temporary = makeScratch();
    return static_cast<T&>(*temporary);
  }
  virtual double doPotentialEnergy(const Stage& /*s*/) const { return 0.0; }
  virtual double doPower(const Stage& /*s*/) const { return 0.0; }
  virtual std::uint64_t doRegime(const Stage& /*s*/) const { return 0; }

 private:
  std::string name_;
};

}  // namespace yardsim::forces
