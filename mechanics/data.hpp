#pragma once
// The mutable workspace of one mechanical system (the System is the immutable side): the
// multibody kernel as the integrators' acceleration source, kinematics workspaces for channels,
// power, events and joint reactions, and the set-point forces, all preallocated so that a stage
// allocates nothing. setPoints points at the set-points in force while a step is integrated.
#include <vector>

#include <Eigen/Core>

#include "dynamics/data.hpp"
#include "dynamics/external_forces.hpp"
#include "dynamics/multibody_system.hpp"
#include "mechanics/set_points.hpp"
#include "mechanics/system.hpp"

namespace yardsim::mechanics {

struct Data {
  explicit Data(const System& s);
  dynamics::MultibodySystem kernel;   // ABA / hybrid / loops with the stage's forces
  dynamics::Data scratch;             // kinematics for power, events and blow-up checks
  dynamics::Data view;                // kinematics of the committed state, for channels
  dynamics::Data feedforward;         // bias forces h(q, v) for the servos
  dynamics::Data reaction;            // RNEA for the joint reactions
  dynamics::ExternalForces spForces;  // the set-point forces (actor loads), for their power
  Eigen::VectorXd spTau;              // the servos' joint forces, N m or N
  std::vector<char> prescribedMask;   // per dof: its motion is prescribed
  Eigen::VectorXd prescribedAcc;      // zero: constant-speed ramps and locks
  Eigen::VectorXd accelScratch;       // velocity steps and accelerations, per dof
  const SetPoints* setPoints = nullptr;
};

}  // namespace yardsim::mechanics
