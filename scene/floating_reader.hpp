#pragma once
// The floating-body part of a mechanics mapping (docs/hydrostatics.md): `water` (density, level,
// depth, waves, wave_ramp, current), `wind` (speed, direction, profile, ...), and the providers
// `hydrostatics` (hull meshes found relative to the YAML file that names them), `wind_loads`,
// `current_loads`, `damping` and `hydrodynamics` (impulse response or a time-domain method,
// docs/hydrodynamics.md), each a mapping of named providers on bodies.
#include <set>
#include <string>

#include "scene/mechanics_reader.hpp"
#include "mechanics/description.hpp"

namespace yardsim::scene {

using mechanics::MechanicsSpec;
using models::Params;

// (params, where to report, the body names known here) => spec's environment and floating
// providers; every problem reported at its node. Parameters that are not set are skipped.
void parseFloating(const Params& p, const MechanicsReport& report, const std::set<std::string>& bodies,
                   MechanicsSpec& spec);

}  // namespace yardsim::scene
