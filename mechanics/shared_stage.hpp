#pragma once
// Whether a system's stage at one state can be evaluated once and read twice: the joint
// reactions read the stage at the committed state (t, q, v), which the next step's first
// integrator stage evaluates at the same (t, q, v) just before (dtss/stepper.hpp: the look-ahead
// step is taken before the committed state is sampled). Reading the kept first stage instead of
// evaluating it again gives the same doubles, and leaves the next steps as they were, only when
// the evaluation is a pure function of (t, q, v, the set-points, the step's start) that leaves
// nothing a later evaluation or output reads.
#include "mechanics/data.hpp"
#include "mechanics/system.hpp"

namespace yardsim::mechanics {

/// (system, its workspace with every provider's scratch) => true when no provider switches
/// (a contact's branch set), no provider keeps a scratch other than a rope's path points (which
/// every evaluation writes before it reads them; another scratch may carry a warm start, a
/// memory or a cache that the evaluation at the committed state would update and that later
/// stages and outputs read), and no body's mass follows the draft or a winch (the stage writes
/// the reactions' added mass)
bool stageShareable(const System& s, const Data& d);

}  // namespace yardsim::mechanics
