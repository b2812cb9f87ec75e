#pragma once
// A loop closure must be closed where the scene starts: frame_a on body_a and frame_b on body_b
// meet (to kMaxInitialLoopGap) at the initial joint positions. A loop open by metres would be
// pulled shut in the first step (a body "teleported", or a blow-up) instead of being refused.
#include <string>
#include <utility>
#include <vector>

#include "mechanics/description.hpp"
#include "models/diagnostics.hpp"
#include "scene/scene.hpp"

namespace yardsim::scene {

inline constexpr double kMaxInitialLoopGap = 1.0e-2;  // m (position rows) or rad (rotation rows)

// (built mechanics) => (loop name, message) for every loop open at the start by more than
// kMaxInitialLoopGap
std::vector<std::pair<std::string, std::string>> openLoops(const mechanics::BuiltMechanics& built);

// (scene with its mechanical systems built) => an error naming every loop open at the start by
// more than kMaxInitialLoopGap, with its gap
void checkInitialLoops(const Scene& scene, models::Diagnostics& diags);

}  // namespace yardsim::scene
