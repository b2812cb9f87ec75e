#include <cstdio>

#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"
#include "cli/scene_input.hpp"
#include "scene/resolved_listing.hpp"

namespace yardsim::cli {

int validateCommand(const std::string& file, bool printResolved) {
  auto scene = loadAndReport(file);
  if (!scene) return kInvalidInput;
  if (printResolved) std::fputs(scene::resolvedListing(*scene).c_str(), stdout);
  else std::printf("%s: valid\n", file.c_str());
  return kOk;
}

}  // namespace yardsim::cli
