#pragma once
// Scene type `multibody`: one mechanically connected system as a DTSS atomic, a thin adaptor over
// mechanics/ (System, stage function, energy balance, event table, blow-up checks). It steps the
// system with the integrator the options name, from grid point to grid point at step dt (an
// adaptive method takes its own steps inside each); the integrator restarts its history whenever
// the state or the set-points change between steps; set-points from actors (`setpoint` port) are
// part of the state and act inside every integrator stage; the located state events of the
// system's event table (a drive reached its target, a rope passed its breaking load, went slack
// or taut, a watched quantity crossed its threshold) are reported on the `event` port.
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dtss/atomic.hpp"
#include "dynamics/integrators/factory.hpp"
#include "mechanics/blowup.hpp"
#include "mechanics/data.hpp"
#include "mechanics/events.hpp"
#include "mechanics/set_points.hpp"
#include "mechanics/system.hpp"
#include "models/channels.hpp"
#include "models/multibody/messages.hpp"
#include "models/multibody/multibody_state.hpp"
#include "models/replay.hpp"

namespace yardsim::models {

struct MultibodyOptions {
  double dt = 1e-3;  // s: the DTSS step, and the integrator's (integrator.dt is ignored)
  dynamics::IntegratorSpec integrator;  // method and its parameters (docs/integrators.md)
  double driveBandwidth = 0.0;          // rad/s of the joint servos; 0: min(10, 0.1/dt)
  double driveMaxEffort = 0.0;          // N m or N; 0: unbounded
  double driveTolerance = 1e-3;         // rad or m: a drive has reached its target within this
  bool projectLoops = true;             // false: no projection even if integrator.loops asks for it
  bool equilibrium = false;             // move q0 to static equilibrium (v = 0) before the run
  bool elementPaths = false;  // channel names are the elements' full paths (scene mechanics)
  // blow-up bounds (docs/numerics.md): the energy balance may rise by at most this fraction of
  // the system's energy scale (total weight x its size, plus its initial kinetic and strain
  // energy); a loop residual may reach at most this, m (or rad)
  double energyGrowthLimit = 1.0;
  double loopResidualLimit = 1e-3;
};

class MultibodyModel final : public dtss::Atomic<MultibodyState>,
                             public Observable,
                             public Replayable {
 public:
  MultibodyModel(std::string name, mechanics::BuiltMechanics mechanics,
                 const MultibodyOptions& options);
  devs::InPort<SetPoint>& setpoint = addInPort<SetPoint>("setpoint");
  devs::OutPort<MechanicsEvent>& event = addOutPort<MechanicsEvent>("event");

  const mechanics::System& system() const { return system_; }
  const dynamics::Model& mechanics() const { return system_.model(); }
  const mechanics::BuiltMechanics& builtMechanics() const { return system_.description(); }
  const MultibodyOptions& options() const { return opt_; }
  void channels(std::vector<Channel>& out) const override;
  bool channelNamesArePaths() const override { return opt_.elementPaths; }
  // (committed state) => kinetic + gravity potential + stored energy, J
  double energy() const;
  // rope i of system().ropes(): the wire ropes, then the equalizers
  const forces::Rope& rope(std::size_t i) const { return *system_.ropes()[i]; }
  // per rope: the tension of one part at the start (after equilibrium, if asked for), N
  const std::vector<double>& initialTension() const { return initialTension_; }
  const std::vector<std::unique_ptr<forces::Hydrostatics>>& hydrostatics() const {
    return system_.hydrostatics();
  }
  // (committed state) => joint accelerations (dv/dt), with the set-points in force
  const Eigen::VectorXd& acceleration() const;
  // (joint name) => body index, or -1
  int jointBody(const std::string& joint) const { return system_.jointBody(joint); }
  // (committed state) => per body, the spatial force its joint transmits to it (world frame,
  // moment about the world origin first), by RNEA with the accelerations and all forces; trees
  const std::vector<dynamics::Force>& jointForces() const;
  // work of the integrator since the start: steps, ABA evaluations, Jacobians, Newton iterations
  const dynamics::IntegratorStats& integratorStats() const { return ws_.integrator->stats(); }
  const dynamics::Integrator& integrator() const { return *ws_.integrator; }
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
  // checkpoints: the power carried into the next step (the winches' pieces are in the state and
  // restored into the ropes); an integrator with a history restarts it at the checkpoint (in the
  // run that writes it and in the run restarted from it alike)
  void saveWorkspace(devs::CheckpointWriter& w) const override;
  void loadWorkspace(devs::CheckpointReader& r) override;
  void afterCheckpoint() override;

 private:
  // (initial state) => static equilibrium, or a NumericalError saying why not
  void settle();
  // (x, new velocity of the prescribed dofs in dv, t) => x.v after the impulse, its work in
  // x.work
  void prescribedVelocityStep(MultibodyState& x, const Eigen::VectorXd& dv, double t) const;
  // (committed state) => the kernel's stage there: ws_.accel, and its external forces (nullptr:
  // none), valid until the kernel's next evaluation; the look-ahead step's first stage when it was
  // kept at this state (keptStageHere()), else evaluated
  const dynamics::ExternalForces* evaluateCommitted() const;
  // (committed state) => the kernel kept the look-ahead step's first stage at this (t, q, v) bit
  // for bit, with this step start, and the system's stage may be shared (stageShareable)
  bool keptStageHere() const;
  // (set-points or the state changed outside a step) => the power and event functions of the
  // last step's end, and the kept first stage, are not reused
  void dropStepCaches() const {
    ws_.powerState = nullptr;
    ws_.events.valid = false;
    ws_.data.kernel.dropKeptStage();
    ws_.stepEnds[0].valid = ws_.stepEnds[1].valid = false;
  }
  // (committed state) => data holds its forward kinematics (cached by time)
  const dynamics::Data& kinematicsOf(const MultibodyState& x) const;
  // (committed state, the provider to read, if it needs its scratch) => the stage it sees there
  forces::Stage committedStage(const forces::ForceProvider* p = nullptr) const;
  // (floating providers) => their channels (multibody_channels.cpp)
  void floatingChannels(std::vector<Channel>& out) const;
  // (hydrostatics k) => its report at the committed state, computed once per time and q
  const forces::HydrostaticReport& hydrostaticReport(std::size_t k) const;
  // (state after a step to t) => throws NumericalError when mechanics::checkBlowUp finds one;
  // else its energy, kept for the energy channels when the stage may be shared (stepEnds)
  void checkBlowUp(const MultibodyState& x, double t) const;

  MultibodyOptions opt_;
  mechanics::System system_;
  std::vector<mechanics::EventSlot> events_;
  std::vector<dtss::Crossing> directions_;
  mechanics::BlowUpLimits limits_;
  std::vector<double> initialTension_;
  // Everything that changes while the state is advanced and read: the mechanics workspace, the
  // integrator (its history restarts at every discontinuity) and caches of the committed state.
  struct Workspace {
    explicit Workspace(const mechanics::System& s) : data(s) {}
    mechanics::Data data;
    std::unique_ptr<dynamics::Integrator> integrator;
    Eigen::VectorXd accel;  // accelerations of the committed state, for channels
    // the system's stage may be evaluated once for a step's first stage and the committed
    // state's reactions (mechanics/shared_stage.hpp); the step start of the stage the kernel keeps
    bool shareStage = false;
    double keptStepStart = 0.0;
    // a reader asked for the committed state's stage (evaluateCommitted) or energy (energy())
    // once: from then on the steps keep them (a run that never reads them pays no copies)
    bool stageRead = false, energyRead = false;
    double accelTime = -1.0, viewTime = -1.0, reactionTime = -1.0, energyTime = -1.0;
    double energy = 0.0;               // the committed state's energy, at energyTime
    Eigen::VectorXd energyQ, energyV;  // ... and at these q and v
    // the energies of the last two steps' ends, from the blow-up check at (t, q, v): a step's end
    // is the committed state that the next rows read (kept when shareStage: then the energy is
    // a function of t, q and v alone, the same doubles)
    struct StepEnd {
      bool valid = false;
      double t = 0.0, energy = 0.0;
      Eigen::VectorXd q, v;
    } stepEnds[2];
    int lastStepEnd = 0;
    const MultibodyState* viewState = nullptr;
    // the power at the end of the last step, reused at the start of the next one
    const MultibodyState* powerState = nullptr;
    double powerTime = -1.0, power = 0.0;
    // per hydrostatics provider: the report of the committed state (time, q), for its channels
    std::vector<forces::HydrostaticReport> reports;
    std::vector<double> reportTime;
    std::vector<Eigen::VectorXd> reportQ;
    // the event functions g last evaluated, at (t, q, v) compared bit for bit: a step starts
    // where the last one ended, so its start's g are its predecessor's end's. Valid while the
    // set-points stay (dropped with powerState wherever they change: dropStepCaches)
    struct {
      bool valid = false;
      double t = 0.0;
      Eigen::VectorXd q, v;
      std::vector<double> g;
    } events;
  };
  mutable Workspace ws_;
};

}  // namespace yardsim::models
