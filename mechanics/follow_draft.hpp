#pragma once
// The added mass of the bodies whose added mass follows their draft (forces/hydro/
// draft_added_mass.hpp), written where the kernels read it (dynamics::Data::addedMass) before
// they run: the stage's ABA, the servos' bias forces and the joint reactions' RNEA, and the
// kinetic energy of the energy balance. A system without such a body does nothing here.
#include "dynamics/data.hpp"
#include "mechanics/system.hpp"

namespace yardsim::mechanics {

/// (system, kinematics of the stage in kin: X_WB) => the added mass of each draft-following body
/// at that pose, written into target (kin itself or another workspace of the same model);
/// allocation-free
void followDraft(const System& s, const dynamics::Data& kin, dynamics::Data& target);

}  // namespace yardsim::mechanics
