#pragma once
// One function per subcommand; each returns the exit status.
#include <string>
#include <vector>

namespace yardsim::cli {

struct RunArgs {
  std::string scene, outdir = "out";
  double until = -1.0;  // < 0: the scene's own
  std::vector<std::string> trace;
  bool traceGiven = false;
  bool quiet = false;
};
int runCommand(const RunArgs& a);

struct WpArgs {
  std::string scene, outdir = "out";
  int repeats = 0;  // 0: the scene's wp.repeats
  bool quiet = false;
};
int wpCommand(const WpArgs& a);

int validateCommand(const std::string& scene, bool printResolved);

struct TraceArgs {
  std::string file;
  std::string model = "*", port = "*";
  double from = -1e300, to = 1e300;
};
int traceCommand(const TraceArgs& a);

int listTypesCommand();
int listChannelsCommand(const std::string& scene);

}  // namespace yardsim::cli
