#pragma once
// (description) => the built mechanics: the immutable dynamics::Model (added mass from given
// matrices or from hull meshes by the Rankine-panel solver at the initial pose), q0, v0 and the
// per-body names, holds and visuals.
#include <string>

#include "mechanics/description.hpp"

namespace yardsim::mechanics {

// (spec) => "" or what is missing for its loads: a wind load without `wind:`, a current load
// without `water: {current}`
std::string missingEnvironment(const MechanicsSpec& spec);

// (spec) => model and initial state; throws dynamics::ModelError naming the body
BuiltMechanics buildMechanics(const MechanicsSpec& spec);

}  // namespace yardsim::mechanics
