#pragma once
// The stiffness guard (docs/numerics.md): before a run, each mechanical system's highest
// frequency omega_max (multibody/stiffness_estimate.hpp) is compared with the chosen method's
// stability limit: omega_max dt must stay inside the method's stability region on the imaginary
// axis (RK4 2.83, semi-implicit Euler 2, AB3 0.72, AB4 0.43; explicit Euler and AB2 grow every
// undamped mode). The scene's `integrator: {stiffness_check: warn | refuse | off}` chooses a
// warning or an error; either suggests a step that works or an implicit method.
// Beside it, each provider that marches at a step of its own (rankine_td's free surface, emp
// scheme: g lambda_max dt^2 <= 4) is judged against that step's limit, with both numbers and the
// mechanical step's: above the limit, within 10 % of it, or not a whole multiple of the mechanics
// step is a warning or an error (the same stiffness_check); run.json gives the figures
// (systems[].marching).
#include <limits>
#include <string>
#include <string_view>

#include "models/diagnostics.hpp"
#include "mechanics/step_verdict.hpp"
#include "scene/scene.hpp"

namespace yardsim::scene {

using models::Diagnostics;

// a marched provider's step beyond this fraction of its stability limit is reported
inline constexpr double kMarchingMargin = 0.9;

// (scene with its mechanical systems) => an error when the step is longer than the run; per
// system, a warning or an error (per scene.stiffnessCheck) when its step is beyond the
// method's stability limit
void checkStiffness(const Scene& scene, Diagnostics& diags);

}  // namespace yardsim::scene
