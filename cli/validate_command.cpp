#include <cstdio>

#include <yaml-cpp/yaml.h>

#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"
#include "cli/scene_input.hpp"
#include "scene/resolved_listing.hpp"
#include "studies/work_precision_reader.hpp"

namespace yardsim::cli {

int validateCommand(const std::string& file, bool printResolved) {
  auto scene = loadAndReport(file);
  if (!scene) return kInvalidInput;
  // (a `wp:` block) => checked as `yardsim wp` would read it
  if (YAML::LoadFile(file)["wp"]) {
    models::Diagnostics d;
    studies::parseWpSpec(*scene, d);
    for (const auto& e : d.all()) std::fprintf(stderr, "%s\n", models::format(e).c_str());
    if (d.hasErrors()) {
      std::fprintf(stderr, "%s: %zu error(s) in the wp: block\n", file.c_str(), d.errorCount());
      return kInvalidInput;
    }
  }
  if (printResolved) std::fputs(scene::resolvedListing(*scene).c_str(), stdout);
  else std::printf("%s: valid\n", file.c_str());
  return kOk;
}

}  // namespace yardsim::cli
