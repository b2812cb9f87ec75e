// The multibody model's readers of its committed state (multibody_model.hpp): the kinematics,
// accelerations, joint reactions, energy and provider stages that its channels and replay read.
#include "dynamics/kinematics.hpp"
#include "dynamics/rnea.hpp"
#include "mechanics/energy.hpp"
#include "models/multibody/multibody_model.hpp"
#include "models/multibody/same_bits.hpp"

namespace yardsim::models {

const dynamics::Data& MultibodyModel::kinematicsOf(const MultibodyState& x) const {
  if (ws_.viewState != &x || ws_.viewTime != state().tx) {
    dynamics::forwardKinematics(system_.model(), ws_.data.view, x.q, x.v);
    ws_.viewState = &x;
    ws_.viewTime = state().tx;
  }
  return ws_.data.view;
}

const Eigen::VectorXd& MultibodyModel::acceleration() const {
  // (committed state, set-points in force) => accelerations, cached by time
  const auto& s = state();
  if (ws_.accelTime != s.tx || ws_.accel.size() != s.x.v.size()) evaluateCommitted();
  return ws_.accel;
}

bool MultibodyModel::keptStageHere() const {
  const auto& s = state();
  const auto& kept = ws_.data.kernel.keptStage();
  return ws_.shareStage && kept.valid && kept.t == s.tx &&
         ws_.keptStepStart == ws_.data.stepStart && sameBits(kept.q, s.x.q) &&
         sameBits(kept.v, s.x.v);
}

const dynamics::ExternalForces* MultibodyModel::evaluateCommitted() const {
  // (committed state, set-points in force) => the kernel's stage: accelerations, and the forces
  // of that stage; the kept first stage of the look-ahead step when it is this one (the same
  // providers at the same state in the same order: the same doubles)
  const auto& s = state();
  ws_.accelTime = s.tx;
  ws_.stageRead = true;
  if (keptStageHere()) {
    const auto& kept = ws_.data.kernel.keptStage();
    ws_.accel = kept.a;
    return kept.forces.empty() ? nullptr : &kept.forces;
  }
  ws_.accel.resize(s.x.v.size());
  ws_.data.setPoints = &s.x.setPoints;
  ws_.data.kernel.acceleration(s.tx, s.x.q, s.x.v, ws_.accel);
  return ws_.data.kernel.stageExternalForces();
}

const std::vector<dynamics::Force>& MultibodyModel::jointForces() const {
  // (committed state, its accelerations, every force) => RNEA's joint forces, cached by time. The
  // stage is taken here, not from acceleration()'s cache, so that the forces are this stage's:
  // RNEA reuses them instead of evaluating the providers a second time
  const auto& s = state();
  auto& d = ws_.data;
  if (ws_.reactionTime != s.tx) {
    const dynamics::ExternalForces* f = evaluateCommitted();
    dynamics::rneaWorld(system_.model(), d.reaction, s.x.q, s.x.v, ws_.accel, f);
    ws_.reactionTime = s.tx;
  }
  return d.reaction.F_W;
}

double MultibodyModel::energy() const {
  // (committed state) => its energy, cached by time, q and v (the energy and energy_balance
  // channels of one row read it twice)
  const auto& s = state();
  ws_.energyRead = true;
  if (ws_.energyTime != s.tx || ws_.energyQ.size() != s.x.q.size() || ws_.energyQ != s.x.q ||
      ws_.energyV.size() != s.x.v.size() || ws_.energyV != s.x.v) {
    // (a step's end that is this state) => the blow-up check's energy there, else computed
    const auto here = [&s](const Workspace::StepEnd& e) {
      return e.valid && e.t == s.tx && sameBits(e.q, s.x.q) && sameBits(e.v, s.x.v);
    };
    const Workspace::StepEnd* end =
        here(ws_.stepEnds[ws_.lastStepEnd])       ? &ws_.stepEnds[ws_.lastStepEnd]
        : here(ws_.stepEnds[1 - ws_.lastStepEnd]) ? &ws_.stepEnds[1 - ws_.lastStepEnd]
                                                  : nullptr;
    ws_.energy = end != nullptr
                     ? end->energy
                     : mechanics::energy(system_, ws_.data, ws_.data.view, s.x.q, s.x.v, s.tx);
    ws_.energyTime = s.tx;
    ws_.energyQ = s.x.q;
    ws_.energyV = s.x.v;
  }
  return ws_.energy;
}

forces::Stage MultibodyModel::committedStage(const forces::ForceProvider* p) const {
  const auto& s = state();
  forces::Stage stage = ws_.data.stage(system_, s.tx, kinematicsOf(s.x), s.x.q, s.x.v);
  if (p != nullptr) stage.scratch = ws_.data.scratchOf(system_, *p);
  return stage;
}

}  // namespace yardsim::models
