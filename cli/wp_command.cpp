#include <cstdio>

#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"
#include "cli/scene_input.hpp"
#include "studies/work_precision.hpp"
#include "studies/work_precision_output.hpp"

namespace yardsim::cli {

int wpCommand(const WpArgs& a) {
  auto scene = loadAndReport(a.scene);
  if (!scene) return kInvalidInput;
  models::Diagnostics diags;
  studies::WpSpec spec = studies::parseWpSpec(*scene, diags);
  if (a.repeats > 0) spec.repeats = a.repeats;
  for (const auto& d : diags.all()) std::fprintf(stderr, "%s\n", models::format(d).c_str());
  if (diags.hasErrors()) return kInvalidInput;
  if (!prepareOutputFolder(a.outdir)) return kInvalidInput;
  try {
    const auto log = [&](const std::string& line) {
      if (!a.quiet) std::fprintf(stderr, "wp: %s\n", line.c_str());
    };
    const studies::WpResult r = studies::workPrecision(*scene, spec, log);
    studies::writeWp(r, spec, a.outdir);
    std::fputs(studies::wpSummary(r, spec).c_str(), stdout);
    std::printf("\nwritten: %s/wp.csv, wp.html, summary.md\n", a.outdir.c_str());
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "%s: %s\n", a.scene.c_str(), e.what());
    return kInvalidInput;
  }
  return kOk;
}

}  // namespace yardsim::cli
