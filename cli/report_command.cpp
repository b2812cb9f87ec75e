#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"
#include "cli/logging.hpp"
#include "output/report_writer.hpp"

namespace yardsim::cli {

int reportCommand(const std::string& outdir, bool quiet) {
  if (!std::filesystem::is_directory(outdir)) {
    std::fprintf(stderr, "report: '%s' is not a folder (expected the output folder of `yardsim run`)\n",
                 outdir.c_str());
    return kInvalidInput;
  }
  if (!std::filesystem::exists(std::filesystem::path(outdir) / "timeseries.csv")) {
    std::fprintf(stderr, "report: '%s' has no timeseries.csv (run a scene with a record: block into it)\n",
                 outdir.c_str());
    return kInvalidInput;
  }
  try {  // (the run's files) => the page; a damaged file is the user's input, named with its line
    output::writeReport(outdir);
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "report: %s\n", e.what());
    return kInvalidInput;
  }
  if (!quiet)
    logger("cli")->info("report: {}", (std::filesystem::path(outdir) / "report.html").string());
  return kOk;
}

}  // namespace yardsim::cli
