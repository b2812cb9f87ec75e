#pragma once
// The mutable workspace of one mechanical system (the System is the immutable side): the
// multibody kernel as the integrators' acceleration source, kinematics workspaces for channels,
// power, events and joint reactions, the set-point forces and every provider's scratch, all
// preallocated so that a stage allocates nothing. setPoints points at the set-points in force
// while a step is integrated; stepStart is the start of that step.
#include <limits>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "dynamics/data.hpp"
#include "dynamics/external_forces.hpp"
#include "dynamics/multibody_system.hpp"
#include "dynamics/rnea.hpp"
#include "forces/force_provider.hpp"
#include "mechanics/set_points.hpp"
#include "mechanics/system.hpp"

namespace yardsim::mechanics {

struct Data {
  explicit Data(const System& s);
  dynamics::MultibodySystem kernel;   // ABA / hybrid / loops with the stage's forces
  dynamics::Data scratch;             // kinematics for power, events and blow-up checks
  dynamics::Data scratch2;            // the second of scratchKinematics' two slots
  struct KinematicsSlot {             // the state whose forwardKinematics a slot holds
    Eigen::VectorXd q, v;
    bool holds = false;
  };
  KinematicsSlot slots[2];            // for scratch and scratch2
  int lastSlot = 0;                   // the slot used last
  dynamics::Data view;                // kinematics of the committed state, for channels
  dynamics::Data feedforward;         // bias forces h(q, v) for the servos
  std::vector<char> drivenJoints;     // per body: its joint is servo-driven at this stage
  dynamics::SubtreeMask feedforwardMask;  // their subtrees and supports (the feedforward's RNEA)
  dynamics::Data reaction;            // RNEA for the joint reactions
  dynamics::ExternalForces spForces;  // the set-point forces (actor loads), for their power
  Eigen::VectorXd spTau;              // the servos' joint forces, N m or N
  std::vector<char> prescribedMask;   // per dof: its motion is prescribed
  Eigen::VectorXd prescribedAcc;      // zero: constant-speed ramps and locks
  Eigen::VectorXd accelScratch;       // velocity steps and accelerations, per dof
  const SetPoints* setPoints = nullptr;
  double stepStart = std::numeric_limits<double>::infinity();  // s (forces::Stage::stepStart)
  // per provider of the system, in the order of System::providers(): its scratch, or nullptr
  std::vector<std::unique_ptr<forces::ProviderScratch>> providerScratch;

  // (t, kinematics of (q, v), q, v) => the stage the providers see, with the step start
  forces::Stage stage(const System& s, double t, const dynamics::Data& kin,
                      const Eigen::VectorXd& q, const Eigen::VectorXd& v) const {
    return forces::Stage{t, s.model(), kin, q, v, nullptr, stepStart};
  }
  // (q, v) => scratch or scratch2, holding forwardKinematics(q, v): computed into the slot used
  // less recently unless one holds them already. Two slots: a step's event functions at its
  // start and end, its power and its energy balance share one pass per committed state (the
  // same doubles). A caller that writes scratch otherwise calls scratchWritten().
  dynamics::Data& scratchKinematics(const System& s, const Eigen::VectorXd& q,
                                    const Eigen::VectorXd& v);
  void scratchWritten() { slots[0].holds = false; }
  // (provider of the system) => its scratch here (nullptr when it needs none)
  forces::ProviderScratch* scratchOf(const System& s, const forces::ForceProvider& p) const;
};

// (stage, visit(provider, the stage with its scratch)) => every provider of the system, in order
template <class Visit>
void forEachProvider(const System& s, const Data& d, const forces::Stage& stage, Visit&& visit) {
  forces::Stage own = stage;
  const auto& providers = s.providers();
  for (std::size_t i = 0; i < providers.size(); ++i) {
    own.scratch = d.providerScratch[i].get();
    visit(*providers[i], static_cast<const forces::Stage&>(own));
  }
}

}  // namespace yardsim::mechanics
