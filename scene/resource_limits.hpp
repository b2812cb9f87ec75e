#pragma once
// Ceilings on what one run may cost, checked before anything runs: the number of steps of every
// fixed-step model (until / dt, until / period) and of recorded rows (until / record.interval).
// A scene that needs more raises them with the root key `limits: {steps: N, rows: N}`
// (docs/scenes.md, "Resource limits"); a step of 1e-300 s is refused instead of running forever.
#include <string>

#include "models/diagnostics.hpp"
#include "scene/scene.hpp"

namespace yardsim::scene {

// (scene, end time s, who set it: "" for the scene's own `until`, else e.g. "--until") => an
// error at the step, period or record interval for every grid above its ceiling
void checkResourceLimits(const Scene& scene, double until, const std::string& untilFrom,
                         models::Diagnostics& diags);

}  // namespace yardsim::scene
