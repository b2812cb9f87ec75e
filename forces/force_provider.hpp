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
#include <stdexcept>
#include <string>

#include <Eigen/Core>

#include "dynamics/data.hpp"
#include "dynamics/external_forces.hpp"
#include "dynamics/model.hpp"

namespace yardsim::forces {

// What a provider sees at one integrator stage: data holds forwardKinematics(q, v) (X_WB, V).
struct Stage {
  double t;
  const dynamics::Model& model;
  const dynamics::Data& data;
  const Eigen::VectorXd& q;
  const Eigen::VectorXd& v;
};

// A provider produced a non-finite force, or was given a state it cannot handle.
class ForceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class ForceProvider {
 public:
  explicit ForceProvider(std::string name) : name_(std::move(name)) {}
  virtual ~ForceProvider() = default;
  ForceProvider(const ForceProvider&) = delete;
  ForceProvider& operator=(const ForceProvider&) = delete;

  const std::string& name() const { return name_; }

  // (stage) => forces added to f and generalized forces added to tau (size nv); throws
  // ForceError when what this provider added is not finite. Allocation-free.
  void evaluate(const Stage& s, dynamics::ExternalForces& f, Eigen::VectorXd& tau);
  // (stage) => energy stored by this provider, J (gravity: m g h; a rope: its strain energy)
  double potentialEnergy(const Stage& s) const { return doPotentialEnergy(s); }
  // (stage) => power of the non-conservative part into the system, W (damping <= 0; a winch
  // paying out or hauling in: the rate of change of stored energy it causes)
  double power(const Stage& s) const { return doPower(s); }

 protected:
  virtual void doEvaluate(const Stage& s, dynamics::ExternalForces& f, Eigen::VectorXd& tau) = 0;
  virtual double doPotentialEnergy(const Stage& /*s*/) const { return 0.0; }
  virtual double doPower(const Stage& /*s*/) const { return 0.0; }

 private:
  std::string name_;
};

}  // namespace yardsim::forces
