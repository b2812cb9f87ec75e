#pragma once
// The masses that follow a system's state or time, written where the kernels read them
// (dynamics::Data::addedMass) before they run: the stage's ABA, the servos' bias forces and the
// joint reactions' RNEA, the impulses' mass matrix and the kinetic energy of the energy balance.
// Two kinds: the added mass of the bodies that follow their draft (follow_draft.hpp), and the
// inner nodes of the lumped lines under a winch (crane ropes with mass), whose mass follows the
// rope paid out (forces/lines/lumped_line_provider.hpp, nodeMass(i, t)): the model keeps the
// start's mass and the difference, m_i (l(t)/l - 1) along the three world axes, goes here; it is
// exactly zero (and the slot off) while the rope is at its start length. A system with neither
// does nothing here.
#include "dynamics/data.hpp"
#include "mechanics/system.hpp"

namespace yardsim::mechanics {

/// (system) => it has a body whose mass follows its state or the time
inline bool followsMass(const System& s) {
  return !s.draftAddedMass().empty() || !s.winchedLines().empty();
}

/// (system, t, kinematics of the stage in kin: X_WB) => the added mass of each draft-following
/// body at that pose and of each winched line's inner nodes at t, written into target (kin itself
/// or another workspace of the same model); allocation-free
void followMass(const System& s, double t, const dynamics::Data& kin, dynamics::Data& target);

}  // namespace yardsim::mechanics
