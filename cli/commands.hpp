#pragma once
// One function per subcommand; each returns the exit status.
#include <cstdint>
#include <string>
#include <vector>

namespace yardsim::cli {

struct RunArgs {
  std::string scene, outdir = "out";
  double until = -1.0;  // < 0: the scene's own
  std::vector<std::string> trace;
  bool traceGiven = false;
  bool quiet = false;
  bool report = false;  // also write OUTDIR/report.html (and record trace.jsonl for its timeline)
  // exit 4 when the run raised: "alarm" an alarm (over_mbl, a watch crossed, ...) or a warning
  // (the stiffness guard's, any the run printed); "safety" an alarm only; "" never
  std::string failOn;
  std::uint64_t maxTransitionsPerInstant = 1000000;  // then the run stops (a zero-time loop)
  double checkpointEvery = 0.0;  // s; > 0: OUTDIR/checkpoints/tXXXXXX.XXX.ckpt at its multiples
  std::string restart;           // a checkpoint of this scene to continue from
  std::string format = "csv";    // hdf5: also OUTDIR/timeseries.h5 (the series under /series)
  bool profile = false;          // print the wall time of each phase and output's share (stderr)
};
int runCommand(const RunArgs& a);

// (OUTDIR) => OUTDIR/report.html from what the run left there
int reportCommand(const std::string& outdir, bool quiet);

struct WpArgs {
  std::string scene, outdir = "out";
  int repeats = 0;  // 0: the scene's wp.repeats
  bool quiet = false;
};
int wpCommand(const WpArgs& a);

struct SweepArgs {
  std::string sweep, outdir = "sweep-out";
  std::size_t jobs = 1;       // cases at once (local engine, array task)
  bool slurmArray = false;    // write OUTDIR/sweep.sbatch (a job array) instead of running
  bool arrayTask = false;     // run the chunk SLURM_ARRAY_TASK_ID picks
  std::size_t chunk = 0;      // cases per array task (0: about 100 tasks)
  std::string collect;        // OUTDIR to gather (no sweep file needed)
  bool dryRun = false;        // check, count the cases, run none
  bool quiet = false;
};
int sweepCommand(const SweepArgs& a);

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
