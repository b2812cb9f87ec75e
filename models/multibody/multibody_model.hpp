#pragma once
// Scene type `multibody`: one mechanically connected system as a DTSS atomic. It steps the
// multibody kernel (ABA, or the Schur-complement forward dynamics when it has loops) with the
// integrator the options name, from grid point to grid point at step dt (an adaptive method takes
// its own steps inside each); the integrator restarts its history whenever the state or the
// set-points change between steps; joint drives and body loads set by actors through the
// `setpoint` port are evaluated inside every integrator stage (tight coupling); a drive that
// reaches its target, a rope passing its breaking load, and a rope going taut or slack are
// located state events, reported on the `event` port.
#include <algorithm>
#include <cmath>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dtss/atomic.hpp"
#include "dynamics/integrators/factory.hpp"
#include "dynamics/multibody_system.hpp"
#include "forces/body_load.hpp"
#include "forces/equalizer.hpp"
#include "forces/flow_load.hpp"
#include "forces/hydrostatics.hpp"
#include "forces/linear_quadratic_damping.hpp"
#include "forces/wire_rope.hpp"
#include "models/channels.hpp"
#include "mechanics/description.hpp"
#include "models/multibody/messages.hpp"
#include "models/replay.hpp"

namespace yardsim::models {

using mechanics::BuiltMechanics;

// A joint driven towards a target along a ramp at a given speed: by a bounded servo, or with its
// motion prescribed (the ramp exactly; the joint is locked at the target afterwards).
struct JointDrive {
  bool active = false;
  bool reported = false;  // the "reached" event was sent
  double start = 0.0, target = 0.0, speed = 0.0, t0 = 0.0;
  std::string actor;
  bool prescribed = false;
  // (ramp) => when a prescribed ramp ends
  double tEnd() const { return t0 + std::max(std::abs(target - start) / speed, 1e-9); }
};

// A winch job on a rope: paying out (or hauling in) until tEnd.
struct WinchJob {
  bool active = false;
  double tEnd = 0.0;
  std::string actor;
};

struct BodyLoad {
  Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
};

// The DTSS state: configuration, velocity and the set-points in force.
struct MultibodyState {
  Eigen::VectorXd q, v;
  std::vector<JointDrive> drives;  // per body index (its joint)
  std::vector<BodyLoad> loads;     // per body index
  std::vector<WinchJob> winches;   // per rope
  double work = 0.0;               // J: integral of the power of non-conservative forces
  std::vector<double> peakTension; // N per rope part: the largest tension at any step so far
};
std::ostream& operator<<(std::ostream& os, const MultibodyState& s);

struct MultibodyOptions {
  double dt = 1e-3;             // s: the DTSS step, and the integrator's (integrator.dt is ignored)
  dynamics::IntegratorSpec integrator;  // method and its parameters (docs/integrators.md)
  double driveBandwidth = 0.0;  // rad/s of the joint servos; 0: min(10, 0.1/dt)
  double driveMaxEffort = 0.0;  // N m or N; 0: unbounded
  double driveTolerance = 1e-3; // rad or m: a drive has reached its target within this
  bool projectLoops = true;     // false: no projection even if integrator.loops asks for it
  bool equilibrium = false;     // move q0 to static equilibrium (v = 0) before the run
  bool elementPaths = false;    // channel names are the elements' full paths (scene mechanics)
  // blow-up bounds (docs/numerics.md): the energy balance may rise by at most this fraction of
  // the system's energy scale (total weight x its size, plus its initial kinetic and strain
  // energy); a loop residual may reach at most this, m (or rad)
  double energyGrowthLimit = 1.0;
  double loopResidualLimit = 1e-3;
};

class MultibodyModel final : public dtss::Atomic<MultibodyState>, public Observable, public Replayable {
 public:
  MultibodyModel(std::string name, BuiltMechanics mechanics, const MultibodyOptions& options);
  devs::InPort<SetPoint>& setpoint = addInPort<SetPoint>("setpoint");
  devs::OutPort<MechanicsEvent>& event = addOutPort<MechanicsEvent>("event");

  const dynamics::Model& mechanics() const { return mech_.model; }
  void channels(std::vector<Channel>& out) const override;
  bool channelNamesArePaths() const override { return opt_.elementPaths; }
  // (committed state) => kinetic + gravity potential + stored (rope) energy, J
  double energy() const;
  // (state, time, workspace) => its kinetic + gravity potential + stored energy, J
  double energyOf(const MultibodyState& x, double t, dynamics::Data& d) const;
  // (state) => power of the non-conservative forces (rope damping and winches, drives, loads), W
  double nonConservativePower(const MultibodyState& x, double t) const;
  const forces::WireRope& rope(std::size_t i) const { return *ropes_[i]; }
  const forces::Equalizer& equalizer(std::size_t i) const { return *equalizers_[i]; }
  const std::vector<std::unique_ptr<forces::Hydrostatics>>& hydrostatics() const { return hydros_; }
  // (committed state) => joint accelerations (dv/dt), with the set-points in force
  const Eigen::VectorXd& acceleration() const;
  // (joint name) => body index, or -1
  int jointBody(const std::string& joint) const;
  // (committed state) => per body, the spatial force its joint transmits to it (world frame,
  // moment about the world origin first), by RNEA with the accelerations and all forces; trees
  const std::vector<dynamics::Force>& jointForces() const;
  // work of the integrator since the start: steps, ABA evaluations, Jacobians, Newton iterations
  const dynamics::IntegratorStats& integratorStats() const { return integrator_->stats(); }
  const dynamics::Integrator& integrator() const { return *integrator_; }
  const BuiltMechanics& builtMechanics() const { return mech_; }
  const MultibodyOptions& options() const { return opt_; }
  void replayBodies(Replay& out) const override;
  void replayFrame(Replay& out, std::size_t firstBody) const override;

 protected:
  void advance(MultibodyState& x, devs::Time t, devs::Time dt) const override;
  void applyInput(MultibodyState& x, devs::Time t) const override;
  std::span<const dtss::Crossing> eventDirections() const override { return directions_; }
  void eventFunctions(const MultibodyState& x, devs::Time t, std::span<double> g) const override;
  void outputAt(const MultibodyState& x, devs::Time t, const dtss::Reached& r) const override;
  void onStateEvent(MultibodyState& x, devs::Time t, int event) const override;
  devs::Time nextTimeEvent(const MultibodyState& x, devs::Time t) const override;
  void onTimeEvent(MultibodyState& x, devs::Time t) const override;

 private:
  // (t, q, v, x's set-points) => joint forces of the drives and the body loads
  void setPointForces(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                      const dynamics::Data& data, dynamics::ExternalForces& f,
                      Eigen::VectorXd& tau) const;
  // (state) => data holds its forward kinematics (cached by time)
  const dynamics::Data& kinematicsOf(const MultibodyState& x) const;
  // (rope name) => index, or -1
  int ropeIndex(const std::string& name) const;
  // (initial state) => static equilibrium, or a NumericalError saying why not
  void settle();
  // (x's drives) => which dofs have prescribed motion; true when any
  bool prescribedDofs(const MultibodyState& x) const;
  // (x, new velocity of the prescribed dofs in dv) => x.v after the impulse, its work in x.work
  void prescribedVelocityStep(MultibodyState& x, const Eigen::VectorXd& dv) const;
  // (state after a step to t) => throws NumericalError when it is not finite, its energy balance
  // grew beyond the bound or a loop opened (multibody_blowup.cpp)
  void checkBlowUp(const MultibodyState& x, double t) const;
  // () => the likely cause of a blow-up: omega_max dt against the method's stability limit
  std::string likelyCause() const;
  // () => the energy scale of the blow-up bound, J
  double energyScale() const;

  BuiltMechanics mech_;
  MultibodyOptions opt_;
  std::vector<dtss::Crossing> directions_;
  std::vector<double> servoInertia_;  // per body: joint-space inertia for the servo gains
  mutable dynamics::MultibodySystem system_;
  mutable std::unique_ptr<dynamics::Integrator> integrator_;
  mutable const MultibodyState* current_ = nullptr;  // the state being advanced
  mutable dynamics::Data view_;                      // kinematics for channels
  mutable dynamics::Data feedforward_;               // bias forces for the drives
  mutable dynamics::Data reaction_;                  // RNEA for the joint forces
  mutable double reactionTime_ = -1.0;
  dynamics::MultibodySystem::ForceCallback forces_;  // every force, as evaluated in a stage
  mutable Eigen::VectorXd accel_;                    // accelerations for channels
  mutable double accelTime_ = -1.0;
  mutable double viewTime_ = -1.0;
  mutable const MultibodyState* viewState_ = nullptr;
  mutable std::vector<std::unique_ptr<forces::WireRope>> ropes_;
  mutable std::vector<std::unique_ptr<forces::Equalizer>> equalizers_;
  mutable std::vector<std::unique_ptr<forces::BodyLoad>> bodyLoads_;  // time series from YAML
  // (watch) => the quantity it reads: kind and index (dof, body or rope)
  struct WatchRef {
    enum class Kind { Q, V, Position, Angle, Tension, Length } kind;
    int index, axis;
  };
  std::vector<WatchRef> watchRefs_;
  // (x, t, scratch_ holding x's kinematics) => the watched quantity
  double watched(std::size_t w, const MultibodyState& x, double t) const;
  // floating bodies: hydrostatics, wind and current loads, damping; `loads_` lists them all
  mutable std::vector<std::unique_ptr<forces::Hydrostatics>> hydros_;
  mutable std::vector<std::unique_ptr<forces::FlowLoad>> flows_;
  mutable std::vector<std::unique_ptr<forces::LinearQuadraticDamping>> dampers_;
  std::vector<forces::ForceProvider*> loads_;
  // (committed state) => the stage providers see there, for channels
  forces::Stage committedStage() const;
  // (floating providers) => their channels
  void floatingChannels(std::vector<Channel>& out) const;
  mutable dynamics::Data scratch_;         // kinematics for power and event functions
  mutable dynamics::ExternalForces spForces_;  // set-point forces, for their power
  mutable Eigen::VectorXd spTau_;
  // the power at the end of the last step, reused at the start of the next one
  mutable double powerTime_ = -1.0, power_ = 0.0;
  mutable std::vector<char> prescribedMask_;  // per dof
  mutable Eigen::VectorXd prescribedAcc_;     // zero: constant-speed ramps and locks
  mutable Eigen::VectorXd accelScratch_;
  mutable const MultibodyState* powerState_ = nullptr;
  double energyBound_ = 0.0;  // J: largest rise of the energy balance before it is a blow-up
  double balance0_ = 0.0;     // J: the energy balance at the start
};

}  // namespace yardsim::models
