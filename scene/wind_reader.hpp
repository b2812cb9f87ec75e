#pragma once
// The `wind` block of a mechanics mapping (docs/hydrostatics.md, "Wind" and "Gusts"): speed,
// direction, profile (uniform, power_law, npd), averaging time, air density, minimum height, and
// the optional time-varying `gusts` {spectrum: npd, seed, components, f_min, f_max, height,
// start, ramp}; every problem reported at its node.
#include "scene/spec_reader.hpp"

namespace yardsim::scene {

// (reader of the `wind` parameter, its node, the spec with the water read) => spec.wind, or
// every problem reported
void readWind(const spec::Reader& r, const YAML::Node& n, mechanics::MechanicsSpec& spec);

}  // namespace yardsim::scene
