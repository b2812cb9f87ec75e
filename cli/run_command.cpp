#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"
#include "cli/logging.hpp"
#include "cli/progress.hpp"
#include "cli/scene_input.hpp"
#include "devs/coupled.hpp"
#include "models/channels.hpp"
#include "models/diagnostics.hpp"
#include "output/timeseries_hdf5.hpp"
#include "scene/assembler.hpp"
#include "run/profile.hpp"
#include "run/run_summary.hpp"
#include "run/runner.hpp"
#include "scene/resource_limits.hpp"

namespace yardsim::cli {

int runCommand(const RunArgs& a) {
  run::PhaseTimes phases;
  std::vector<models::Diagnostic> warnings;
  auto scene = loadAndReport(a.scene, &phases, &warnings);
  if (!scene) return kInvalidInput;
  // (--until) => the run's ceilings checked again for the end time given on the command line
  if (a.until >= 0) {
    models::Diagnostics d;
    scene::checkResourceLimits(*scene, a.until, "--until", d);
    for (const auto& e : d.all()) std::fprintf(stderr, "%s\n", models::format(e).c_str());
    if (d.hasErrors()) return kInvalidInput;
  }
  run::RunOptions opt;
  opt.outdir = a.outdir;
  opt.until = a.until >= 0 ? a.until : scene->until;
  // (--checkpoint-every, end time) => a period of at least 1 ms (the resolution of the
  // checkpoints' names) and at most the rows ceiling of checkpoints over a finite end time (a
  // period of 1e-300 s wrote checkpoints without end)
  if (a.checkpointEvery > 0.0) {
    if (a.checkpointEvery < 1e-3) {
      std::fprintf(
          stderr,
          "--checkpoint-every: expected a period of at least 0.001 s (checkpoints are named "
          "by the millisecond, tNNNNNN.NNN.ckpt), got %g s\n",
          a.checkpointEvery);
      return kInvalidInput;
    }
    if (const double count = opt.until / a.checkpointEvery;
        std::isfinite(opt.until) && count > scene->limits.rows) {
      std::fprintf(stderr,
                   "--checkpoint-every: %g s over %g s is %.3g checkpoints, above the ceiling of "
                   "%.3g (the scene's `limits: {rows}`); take a longer period\n",
                   a.checkpointEvery, opt.until, count, scene->limits.rows);
      return kInvalidInput;
    }
  }
  opt.trace = a.traceGiven ? a.trace : scene->trace;
  opt.maxTransitionsPerInstant = a.maxTransitionsPerInstant;
  opt.checkpointEvery = a.checkpointEvery;
  opt.restartFrom = a.restart;
  opt.profile = a.profile;
  opt.warnings = warnings;
  if (a.report && !(scene->record.interval > 0)) {
    std::fprintf(stderr, "%s: --report needs a `record:` block (the report plots what is recorded; "
                         "docs/report.md)\n", a.scene.c_str());
    return kInvalidInput;
  }
  // (--report, no trace.jsonl asked) => the outputs-only trace: what the page reads (actor
  // spans, events), not the per-step records (docs/report.md)
  if (a.report && std::find(opt.trace.begin(), opt.trace.end(), "jsonl") == opt.trace.end() &&
      std::find(opt.trace.begin(), opt.trace.end(), "events") == opt.trace.end())
    opt.trace.push_back("events");
  for (const auto& t : opt.trace)
    if (t != "jsonl" && t != "events" && t != "chrome" && t != "csv") {
      std::fprintf(stderr, "--trace: unknown sink '%s' (expected jsonl, events, chrome or csv)\n",
                   t.c_str());
      return kInvalidInput;
    }
  ProgressPrinter printer;
  if (!a.quiet) opt.progress = [&](const run::Progress& p) { printer(p); };
  auto log = logger("cli");
  // (an alarm's first occurrence) => one console line, also when quiet; notices are summed up at the end
  opt.onAlarm = [&](const run::Alarm& al) {
    if (al.severity != "alarm") return;
    printer.finish();
    std::fprintf(stderr, "ALARM t = %.6g s: %s '%s' %s (%.6g)\n", al.first, al.model.c_str(),
                 al.element.c_str(),
                 al.kind == "over_mbl"         ? "passed its minimum breaking load, tension [N]"
                 : al.kind == "over_hook_load" ? "passed its hook-load curve, hook load [N]"
                                               : "crossed its threshold, value",
                 al.worst);
  };
  if (!prepareOutputFolder(a.outdir)) return kInvalidInput;
  std::unique_ptr<devs::Coupled> root;
  try {  // (scene) => its models; the initial state can fail numerically (no static equilibrium)
    const run::Stopwatch building;
    root = scene::assemble(*scene);
    phases.build = building.seconds();
  } catch (const devs::SimulationError& e) {
    std::fprintf(stderr, "numerical failure before the run: %s\nnothing was simulated\n", e.what());
    // (the failure) => OUTDIR/run.json with status failed and the diagnosis, as after a run
    try {
      std::filesystem::create_directories(a.outdir);
      run::RunFacts facts;
      facts.until = opt.until;
      facts.status = "failed";
      facts.message = e.what();
      devs::Coupled nothing(scene->name);
      run::writeRunSummary(std::filesystem::path(a.outdir) / "run.json", *scene, nothing, facts);
    } catch (const std::exception&) {  // an unwritable folder: the console has the diagnosis
    }
    return kNumericalFailure;
  }
  // (report.static) => every name a channel of the assembled scene, or refused before the run
  {
    std::vector<std::string> names;
    for (const auto& c : models::collectChannels(*root)) names.push_back(c.name);
    models::Diagnostics d;
    for (std::size_t i = 0; i < scene->report.staticLevels.size(); ++i) {
      const std::string& name = scene->report.staticLevels[i].first;
      if (std::find(names.begin(), names.end(), name) == names.end())
        d.error(scene->report.staticWhere[i], "report.static." + name,
                "no channel '" + name + "' in this scene (yardsim list-channels lists them)",
                models::didYouMean(name, names));
    }
    for (const auto& e : d.all()) std::fprintf(stderr, "%s\n", models::format(e).c_str());
    const std::size_t unknown = d.errorCount();
    if (unknown > 0) {
      std::fprintf(stderr, "%s: %zu error(s); nothing was simulated\n", a.scene.c_str(), unknown);
      return kInvalidInput;
    }
  }
  try {
    const run::RunResult r = run::runScene(*scene, *root, opt);
    printer.finish();
    if (!a.quiet)
      log->info("{}: simulated {:.6g} s in {:.3g} s wall (real-time factor {:.3g}), {} samples, "
                "{} transitions; output in {}",
                scene->name, r.tEnd, r.wall, r.wall > 0 ? r.tEnd / r.wall : 0.0, r.samples,
                r.stats.internal + r.stats.external + r.stats.confluent, a.outdir);
    // (alarms) => first time, count and worst value of each; exit 4 when asked to fail on them;
    // a warning (printed in full at the door) by its element, count and value
    for (const auto& al : r.alarms)
      if (al.severity == "warning")
        std::fprintf(stderr, "warning: '%s': %zu time(s) from t = %.6g s, value %.6g\n",
                     al.element.c_str(), al.count, al.first, al.worst);
      else if (al.severity == "alarm" || !a.quiet)
        std::fprintf(stderr,
                     "%s: %s '%s' %s: first at t = %.6g s, %zu time(s), worst %.6g at t = %.6g s\n",
                     al.severity.c_str(), al.model.c_str(), al.element.c_str(), al.kind.c_str(),
                     al.first, al.count, al.worst, al.worstAt);
    const run::Stopwatch writing;
    if (a.format == "hdf5" && r.samples > 0)
      output::writeTimeseriesHdf5(std::filesystem::path(a.outdir) / "timeseries.csv",
                                  std::filesystem::path(a.outdir) / "timeseries.h5");
    // (--fail-on) => which severities make the exit status 4
    const bool alarmed = std::any_of(r.alarms.begin(), r.alarms.end(), [&](const auto& al) {
      return (a.failOn == "alarm" || a.failOn == "safety") && al.severity == "alarm";
    });
    const bool warned = std::any_of(r.alarms.begin(), r.alarms.end(), [&](const auto& al) {
      return a.failOn == "alarm" && al.severity == "warning";
    });
    const int status = a.report ? reportCommand(a.outdir, a.quiet) : kOk;
    // (phase times) => one line on stderr, also when quiet
    if (a.profile) {
      phases.simulate = r.simulateSeconds;
      phases.output = r.outputSeconds + writing.seconds();
      std::fprintf(stderr, "%s\n", run::formatProfile(phases).c_str());
    }
    if (status == kOk && (alarmed || warned)) return kAlarm;
    return status;
  } catch (const devs::CheckpointError& e) {
    printer.finish();
    std::fprintf(stderr, "%s\nnothing was simulated\n", e.what());
    return kInvalidInput;
  } catch (const devs::SimulationError& e) {
    printer.finish();
    std::fprintf(stderr, "numerical failure: %s\neverything recorded until then is in %s\n",
                 e.what(), a.outdir.c_str());
    if (a.report) reportCommand(a.outdir, a.quiet);
    return kNumericalFailure;
  }
}

}  // namespace yardsim::cli
