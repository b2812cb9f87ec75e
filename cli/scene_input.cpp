#include "cli/scene_input.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "scene/scene_loader.hpp"

namespace yardsim::cli {

std::unique_ptr<scene::Scene> loadAndReport(const std::string& file, run::PhaseTimes* times,
                                            std::vector<models::Diagnostic>* warnings) {
  scene::LoadResult r = scene::loadScene(file);
  if (times) {
    times->read = r.readSeconds;
    times->validation = r.validationSeconds;
    times->stiffness = r.stiffnessSeconds;
  }
  for (const auto& d : r.diagnostics.all()) {
    std::fprintf(stderr, "%s\n", models::format(d).c_str());
    if (warnings && d.severity == models::Diagnostic::Severity::Warning) warnings->push_back(d);
  }
  if (!r.scene)
    std::fprintf(stderr, "%s: %zu error(s); nothing was simulated\n", file.c_str(),
                 r.diagnostics.errorCount());
  return std::move(r.scene);
}

bool prepareOutputFolder(const std::string& outdir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (outdir.empty()) {
    std::fprintf(stderr, "-o: expected an output folder, got an empty name\n");
    return false;
  }
  fs::create_directories(outdir, ec);
  if (ec || !fs::is_directory(outdir)) {
    std::fprintf(stderr, "-o: cannot create the output folder '%s': %s\n", outdir.c_str(),
                 ec ? ec.message().c_str() : "a file of that name is in the way");
    return false;
  }
  const fs::path probe = fs::path(outdir) / ".yardsim_write_test";
  const bool writable = static_cast<bool>(std::ofstream(probe));
  fs::remove(probe, ec);
  if (!writable)
    std::fprintf(stderr, "-o: cannot write into the output folder '%s'\n", outdir.c_str());
  return writable;
}

}  // namespace yardsim::cli
