#include "cli/scene_input.hpp"

#include <cstdio>

#include "scene/scene_loader.hpp"

namespace yardsim::cli {

std::unique_ptr<scene::Scene> loadAndReport(const std::string& file, run::PhaseTimes* times) {
  scene::LoadResult r = scene::loadScene(file);
  if (times) {
    times->read = r.readSeconds;
    times->validation = r.validationSeconds;
    times->stiffness = r.stiffnessSeconds;
  }
  for (const auto& d : r.diagnostics.all()) std::fprintf(stderr, "%s\n", models::format(d).c_str());
  if (!r.scene)
    std::fprintf(stderr, "%s: %zu error(s); nothing was simulated\n", file.c_str(),
                 r.diagnostics.errorCount());
  return std::move(r.scene);
}

}  // namespace yardsim::cli
