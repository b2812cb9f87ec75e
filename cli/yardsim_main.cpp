#include "cli/yardsim_main.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "cli/commands.hpp"
#include "cli/db_command.hpp"
#include "cli/exit_codes.hpp"
#include "cli/logging.hpp"
#include "models/diagnostics.hpp"
#include "run/timeseries_writer.hpp"

namespace yardsim::cli {

namespace {
// (option, unit) => a validator refusing a value that is not a finite number >= 0 (nan, inf, -5)
CLI::Validator finiteNonNegative(const std::string& unit) {
  return CLI::Validator(
      [unit](std::string& text) -> std::string {
        double v = 0.0;
        try {
          std::size_t used = 0;
          v = std::stod(text, &used);
          if (used != text.size()) throw std::invalid_argument(text);
        } catch (const std::exception&) {
          return "expected a number of " + unit + ", got '" + text + "'";
        }
        if (!std::isfinite(v) || v < 0.0) return "expected a finite number >= 0 " + unit + ", got " + text;
        return "";
      },
      "finite >= 0");
}
}  // namespace

int yardsimMain(int argc, char** argv) {
  CLI::App app{"yardsim: heavy-lift and marine operation simulator"};
  app.set_version_flag("--version", std::string("yardsim ") + run::kVersion);
  app.require_subcommand(1);

  RunArgs run;
  auto* runCmd = app.add_subcommand("run", "run a scene and write its outputs");
  runCmd->add_option("scene", run.scene, "scene file (YAML)")->required();
  runCmd->add_option("-o,--outdir", run.outdir, "output folder")->capture_default_str();
  runCmd->add_option("--until", run.until, "end time in s (default: the scene's `until`)")
      ->check(finiteNonNegative("s"));
  runCmd
      ->add_option("--trace", run.trace,
                   "trace sinks: jsonl,events,chrome,csv (events: outputs only)")
      ->delimiter(',');
  runCmd->add_flag("--quiet", run.quiet, "no progress or summary");
  runCmd->add_flag("--report", run.report,
                   "also write OUTDIR/report.html (adds the events trace unless jsonl is asked)");
  runCmd->add_flag("--profile", run.profile,
                   "print one line: wall time of reading, validation, stiffness guard, build, simulate and output");
  runCmd->add_option("--max-transitions-per-instant", run.maxTransitionsPerInstant,
                     "stop (exit 2) after this many transitions at one simulated time")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  runCmd
      ->add_option("--fail-on", run.failOn,
                   "exit 4 when the run raised: alarm (a rope over its MBL, a watch crossed, ... "
                   "or a warning such as the stiffness guard's), safety (the alarms only)")
      ->check(CLI::IsMember({"alarm", "safety"}));
  runCmd->add_option("--checkpoint-every", run.checkpointEvery,
                     "write OUTDIR/checkpoints/tXXXXXX.XXX.ckpt every this many simulated s")
      ->check(finiteNonNegative("s"));
  runCmd->add_option("--format", run.format, "csv, or hdf5: also OUTDIR/timeseries.h5 (the series under /series)")
      ->capture_default_str()
      ->check(CLI::IsMember({"csv", "hdf5"}));
  runCmd->add_option("--restart", run.restart,
                     "continue from a checkpoint of this scene (OUTDIR gets what follows it)");

  std::string reportDir;
  bool reportQuiet = false;
  auto* reportCmd = app.add_subcommand("report", "write OUTDIR/report.html from a run's outputs");
  reportCmd->add_option("outdir", reportDir, "output folder of a run")->required();
  reportCmd->add_flag("--quiet", reportQuiet, "no summary");

  WpArgs wp;
  auto* wpCmd = app.add_subcommand("wp", "error against run time: run the scene's `wp:` sweep of integrators");
  wpCmd->add_option("scene", wp.scene, "scene file (YAML) with a wp: block")->required();
  wpCmd->add_option("-o,--outdir", wp.outdir, "output folder (wp.csv, wp.html, summary.md)")->capture_default_str();
  wpCmd->add_option("--repeats", wp.repeats, "timed runs per point after the warm-up (default: wp.repeats)")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            return text.find_first_not_of("0123456789") == std::string::npos && text.find_first_not_of('0') != std::string::npos
                       ? ""
                       : "expected a whole number >= 1, got " + text;
          },
          "whole number >= 1"));
  wpCmd->add_flag("--quiet", wp.quiet, "no per-run log lines");

  SweepArgs sw;
  auto* sweepCmd = app.add_subcommand("sweep", "run a parameter sweep (local cores, MPI ranks or a Slurm array)");
  sweepCmd->add_option("sweep", sw.sweep, "sweep file (YAML, docs/sweeps.md)");
  sweepCmd->add_option("-o,--outdir", sw.outdir, "output folder (cases.csv, sweep.h5, sweep.html)")->capture_default_str();
  sweepCmd->add_option("-j,--jobs", sw.jobs, "cases run at once")->capture_default_str()->check(CLI::PositiveNumber);
  sweepCmd->add_flag("--slurm-array", sw.slurmArray, "write OUTDIR/sweep.sbatch, a Slurm job array, and run nothing");
  sweepCmd->add_flag("--array-task", sw.arrayTask, "run the chunk of cases SLURM_ARRAY_TASK_ID picks (the batch script)");
  sweepCmd->add_option("--chunk", sw.chunk, "cases per array task")->check(CLI::PositiveNumber);
  sweepCmd->add_option("--collect", sw.collect, "gather what the cases of OUTDIR recorded into its results");
  sweepCmd->add_flag("--dry-run", sw.dryRun, "check the sweep and count its cases; run none");
  sweepCmd->add_flag("--quiet", sw.quiet, "no line per case");

  std::string validateScene;
  bool printResolved = false;
  auto* validate = app.add_subcommand("validate", "check a scene without running it");
  validate->add_option("scene", validateScene, "scene file (YAML)")->required();
  validate->add_flag("--print-resolved", printResolved, "list exactly what would run");

  TraceArgs trace;
  auto* traceCmd = app.add_subcommand("trace", "filter and pretty-print a JSON Lines trace");
  traceCmd->add_option("file", trace.file, "OUTDIR/trace.jsonl")->required();
  traceCmd->add_option("--model", trace.model, "glob over model paths")->capture_default_str();
  traceCmd->add_option("--port", trace.port, "glob over port names")->capture_default_str();
  traceCmd->add_option("--from", trace.from, "start time, s")->check(finiteNonNegative("s"));
  traceCmd->add_option("--to", trace.to, "end time, s")->check(finiteNonNegative("s"));

  app.add_subcommand("list-types", "list the registered model types and their parameters");
  std::string channelsScene;
  auto* channels = app.add_subcommand("list-channels", "list the channels a scene can record");
  channels->add_option("scene", channelsScene, "scene file (YAML)")->required();

  DbArgs dbArgs;
  auto* dbCmd = addDbCommand(app, dbArgs);

  // (a first word that is no command) => named, with the commands there are
  if (argc > 1 && argv[1][0] != '-') {
    std::vector<std::string> names;
    for (const auto* c : app.get_subcommands([](const CLI::App*) { return true; })) names.push_back(c->get_name());
    if (std::find(names.begin(), names.end(), argv[1]) == names.end()) {
      const std::string hint = models::didYouMean(argv[1], names);
      std::string all;
      for (const auto& n : names) all += (all.empty() ? "" : ", ") + n;
      std::fprintf(stderr, "yardsim: unknown command '%s'%s; the commands are %s (yardsim --help)\n", argv[1],
                   hint.empty() ? "" : (" (" + hint + ")").c_str(), all.c_str());
      return kInvalidInput;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kOk : kInvalidInput;
  }
  setupLogging();
  try {
    if (runCmd->parsed()) {
      run.traceGiven = runCmd->count("--trace") > 0;
      return runCommand(run);
    }
    if (reportCmd->parsed()) return reportCommand(reportDir, reportQuiet);
    if (wpCmd->parsed()) return wpCommand(wp);
    if (sweepCmd->parsed()) return sweepCommand(sw);
    if (validate->parsed()) return validateCommand(validateScene, printResolved);
    if (traceCmd->parsed()) return traceCommand(trace);
    if (channels->parsed()) return listChannelsCommand(channelsScene);
    if (dbCmd->parsed()) return dbCommand(*dbCmd, dbArgs);
    return listTypesCommand();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "yardsim: internal error: %s\n", e.what());
    return kInternalError;
  }
}

}  // namespace yardsim::cli
