#include "cli/scene_input.hpp"

#include <cstdio>

#include "scene/scene_loader.hpp"

namespace yardsim::cli {

std::unique_ptr<scene::Scene> loadAndReport(const std::string& file) {
  scene::LoadResult r = scene::loadScene(file);
  for (const auto& d : r.diagnostics.all()) std::fprintf(stderr, "%s\n", models::format(d).c_str());
  if (!r.scene)
    std::fprintf(stderr, "%s: %zu error(s); nothing was simulated\n", file.c_str(),
                 r.diagnostics.errorCount());
  return std::move(r.scene);
}

}  // namespace yardsim::cli
