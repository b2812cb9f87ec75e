#include "scene/loop_gap_check.hpp"

#include <cstdio>

#include "dynamics/data.hpp"
#include "dynamics/loop_constraints.hpp"
#include "scene/mechanical_systems.hpp"

namespace yardsim::scene {

std::vector<std::pair<std::string, std::string>> openLoops(const mechanics::BuiltMechanics& built) {
  std::vector<std::pair<std::string, std::string>> out;
  if (built.model.loops.empty()) return out;
  // (model, q0) => each loop's largest residual row at the start
  dynamics::Data data(built.model);
  const Eigen::VectorXd& g = dynamics::loopResidual(built.model, data, built.q0);
  for (const auto& loop : built.model.loops) {
    const double gap = loop.dim > 0 ? g.segment(loop.row, loop.dim).cwiseAbs().maxCoeff() : 0.0;
    if (!(gap > kMaxInitialLoopGap)) continue;
    char text[160];
    std::snprintf(text, sizeof text,
                  "is open by %.4g (m or rad) at the initial joint positions, more than %g", gap,
                  kMaxInitialLoopGap);
    out.emplace_back(loop.name,
                     "loop '" + loop.name + "' " + text +
                         "; place frame_a and frame_b where they meet, or set the joints' q0 so "
                         "that they do");
  }
  return out;
}

void checkInitialLoops(const Scene& scene, models::Diagnostics& diags) {
  // (system, loop name) => the place of the loop's key, found among the system's loops
  for (const auto& system : scene.systems)
    if (system->built)
      for (const auto& [name, message] : openLoops(*system->built)) {
        const auto& loops = system->spec.loops;
        std::size_t i = 0;
        while (i < loops.size() && loops[i].name != name) ++i;
        const bool placed = i < system->loopPlaces.size();
        diags.error(placed ? system->loopPlaces[i].first : scene.integratorWhere,
                    placed ? system->loopPlaces[i].second : "mechanics.loops." + name,
                    "mechanical system '" + system->name + "': " + message);
      }
}

}  // namespace yardsim::scene
