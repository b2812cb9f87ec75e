#include "run/runner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>

#include "devs/chrome_trace_sink.hpp"
#include "devs/csv_trace_sink.hpp"
#include "devs/jsonl_trace_sink.hpp"
#include "dtss/grid.hpp"
#include "models/channels.hpp"
#include "output/gltf_writer.hpp"
#include "output/replay_recorder.hpp"
#include "run/checkpoint_file.hpp"
#include "run/event_trace.hpp"
#include "run/hook_load_monitor.hpp"
#include "run/profile.hpp"
#include "run/run_summary.hpp"
#include "run/timeseries_writer.hpp"
#include "run/watch_extremes.hpp"

namespace yardsim::run {

using models::collectChannels;
using models::selectChannels;
using output::ReplayRecorder;
using output::writeGlb;
using scene::Scene;

namespace {
// What the runner itself carries in a checkpoint: the next record and checkpoint indices, the
// alarms so far and the trace sinks' sequence numbers.
struct RunPosition {
  std::int64_t record = 1, checkpoint = 1;
  double every = 0.0;  // s between checkpoints
  double reached = 0.0;
  std::vector<Alarm> alarms;
  std::vector<std::uint64_t> sequences;  // per record sink, in the order of opt.trace
};

// (position) => appended to the archive
void savePosition(devs::CheckpointWriter& w, const RunPosition& p) {
  w.section("run");
  w.i64(p.record);
  w.i64(p.checkpoint);
  w.f64(p.every);
  w.f64(p.reached);
  w.list(p.alarms.size());
  for (const Alarm& a : p.alarms) {
    for (const auto* s : {&a.model, &a.element, &a.kind, &a.severity, &a.message}) w.str(*s);
    w.f64(a.first);
    w.i64(static_cast<std::int64_t>(a.count));
    w.f64(a.worst);
    w.f64(a.worstAt);
  }
  devs::save(w, p.sequences);
}

// (archive) => the position it holds
RunPosition loadPosition(devs::CheckpointReader& r) {
  RunPosition p;
  r.section("run");
  p.record = r.i64();
  p.checkpoint = r.i64();
  p.every = r.f64();
  p.reached = r.f64();
  p.alarms.resize(r.list());
  for (Alarm& a : p.alarms) {
    for (auto* s : {&a.model, &a.element, &a.kind, &a.severity, &a.message}) *s = r.str();
    a.first = r.f64();
    a.count = static_cast<std::size_t>(r.i64());
    a.worst = r.f64();
    a.worstAt = r.f64();
  }
  devs::load(r, p.sequences);
  return p;
}
}  // namespace

RunResult runScene(const Scene& scene, devs::Coupled& root, const RunOptions& opt) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto wall = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  std::filesystem::create_directories(opt.outdir);

  // (restart) => the checkpoint read and checked against this scene before anything is written
  const std::string fingerprint =
      opt.checkpointEvery > 0.0 || !opt.restartFrom.empty() ? sceneFingerprint(scene) : "";
  CheckpointFile restart;
  RunPosition position;
  std::optional<devs::CheckpointReader> restored;
  if (!opt.restartFrom.empty()) {
    restart = readCheckpointFile(opt.restartFrom, fingerprint);
    restored.emplace(restart.payload);
    position = loadPosition(*restored);
    if (!(restart.t < opt.until))
      throw devs::CheckpointError(opt.restartFrom.string() + ": taken at t = " +
                                  std::to_string(restart.t) + " s, not before the end time " +
                                  std::to_string(opt.until) + " s: nothing is left to run");
  }

  // (output work) => done, its wall time added to `outputSeconds`
  double outputSeconds = 0.0;
  auto output = [&](auto&& work) {
    const Stopwatch w;
    work();
    outputSeconds += w.seconds();
  };
  // (record block) => the recorder, only when the scene asks for one
  std::unique_ptr<TimeseriesWriter> recorder;
  const double interval = scene.record.interval;
  output([&] {
    if (interval > 0.0)
      recorder = std::make_unique<TimeseriesWriter>(
          opt.outdir / "timeseries.csv", scene, selectChannels(collectChannels(root), scene.record.channels),
          restored ? opt.restartFrom.string() + " at " + std::to_string(restart.t) + " s" : "");
    // (initial state) => the first row, on disk before the simulator computes its first step (a
    // step that fails at once still leaves it); a restarted run goes on after its checkpoint's row
    if (recorder && !restored) recorder->sample(0.0);
  });

  // (record grid, frame budget) => replay frames every `stride` samples, from the same t = 0
  ReplayRecorder replay(root);
  std::int64_t stride = 1;
  if (interval > 0.0 && std::isfinite(opt.until) && opt.maxReplayFrames > 0)
    stride = std::max<std::int64_t>(
        1, static_cast<std::int64_t>(std::ceil(opt.until / interval / static_cast<double>(opt.maxReplayFrames))));
  const bool replaying = recorder && !replay.empty();
  AlarmMonitor alarms(opt.onAlarm);
  alarms.restore(position.alarms);
  // (the scene's warnings) => one `warning` each from the start (a restarted run has them)
  for (const auto& d : opt.warnings) alarms.warn(d, restored ? restart.t : 0.0, !restored);
  RunFacts facts;
  facts.until = opt.until;
  facts.replayInterval = replaying ? interval * static_cast<double>(stride) : 0.0;
  double reached = position.reached;  // simulated time, s
  // (facts) => replay.glb and run.json, also when the run fails
  auto finish = [&] {
    facts.tEnd = reached;
    facts.alarms = alarms.alarms();
    raiseToRopePeaks(facts.alarms, root);
    facts.wall = wall();
    output([&] {
      if (replaying) writeGlb(replay.replay(), opt.outdir / "replay.glb");
      writeRunSummary(opt.outdir / "run.json", scene, root, facts);
    });
  };

  RunResult result;
  try {
    devs::Simulator sim(root);
    sim.setInstantLimit(opt.maxTransitionsPerInstant);
    if (opt.checkpointEvery > 0.0 || restored)
      if (const devs::AtomicBase* a = sim.firstUncheckpointable())
        throw devs::CheckpointError("model '" + a->path() +
                                    "' cannot be checkpointed: its state type has no StateCodec "
                                    "(docs/extending.md, checkpoints)");
    // (trace names) => sinks, only those asked for; record sinks go on at their sequence number
    // (events and jsonl both asked) => the full trace alone: it holds the outputs too
    std::vector<std::unique_ptr<devs::Listener>> sinks, filters;
    std::vector<devs::Listener*> profiled;
    std::vector<devs::RecordSink*> records;
    const bool full = std::find(opt.trace.begin(), opt.trace.end(), "jsonl") != opt.trace.end();
    // (trace names) => the sinks made and their files opened, booked as output
    output([&] {
      for (const auto& name : opt.trace) {
        if (name == "events" && full) continue;
        if (name == "jsonl" || name == "events")
          sinks.push_back(std::make_unique<devs::JsonlTraceSink>(
              devs::TraceStream(opt.outdir / "trace.jsonl")));
        else if (name == "chrome")
          sinks.push_back(std::make_unique<devs::ChromeTraceSink>(
              devs::TraceStream(opt.outdir / "trace.json")));
        else if (name == "csv")
          sinks.push_back(
              std::make_unique<devs::CsvTraceSink>(devs::TraceStream(opt.outdir / "trace.csv")));
        else
          throw std::invalid_argument("unknown trace sink '" + name +
                                      "' (expected jsonl, events, chrome or csv)");
        if (auto* r = dynamic_cast<devs::RecordSink*>(sinks.back().get())) records.push_back(r);
        // (events) => the sink sees the outputs only; (profile) => its hooks timed
        devs::Listener* listener = sinks.back().get();
        if (name == "events")
          listener = filters.emplace_back(std::make_unique<OutputsOnly>(*listener)).get();
        if (opt.profile)
          profiled.push_back(listener);
        else
          sim.addListener(*listener);
      }
    });
    // (profile) => the sinks behind one timer, in their order
    std::optional<TimedListener> timed;
    if (!profiled.empty()) sim.addListener(timed.emplace(std::move(profiled), outputSeconds));
    sim.addListener(alarms);
    // (watches) => the worst value of each crossing, read after every step
    WatchExtremes extremes(root, alarms);
    if (!extremes.empty()) sim.addListener(extremes);
    // (cranes of the yard database with a hook-load curve) => checked after every step
    std::optional<HookLoadMonitor> hookLoads;
    if (!scene.hookLoads.empty())
      sim.addListener(hookLoads.emplace(scene.hookLoads, collectChannels(root), alarms));
    if (restored) {
      if (position.sequences.size() == records.size())
        for (std::size_t i = 0; i < records.size(); ++i) records[i]->continueAt(position.sequences[i]);
      sim.loadCheckpoint(*restored);
      if (!restored->atEnd())
        throw devs::CheckpointError(opt.restartFrom.string() + ": bytes left after the last model's state");
    }
    if (replaying) output([&] { replay.sample(reached); });
    double lastReport = 0.0;
    auto report = [&](double t) {
      if (!opt.progress) return;
      const double w = wall();
      if (w - lastReport < opt.progressPeriod) return;
      lastReport = w;
      opt.progress({t, opt.until, w});
    };
    // (simulator, position) => OUTDIR/checkpoints/tXXXXXX.XXX.ckpt
    auto checkpoint = [&](double t) {
      position.reached = reached;
      position.alarms = alarms.alarms();
      position.sequences.clear();
      for (const auto* r : records) position.sequences.push_back(r->sequence());
      devs::CheckpointWriter w;
      savePosition(w, position);
      sim.saveCheckpoint(w);
      writeCheckpointFile(opt.outdir / "checkpoints" / checkpointName(t), fingerprint, t, w.bytes());
    };
    // (options, checkpoint) => the period: a restarted run keeps its checkpoint's unless told
    // otherwise (an adaptive integrator restarts its history at each one: the same cadence
    // keeps the restarted run identical to the one that wrote the checkpoint)
    const double every = opt.checkpointEvery > 0.0 || !restored ? opt.checkpointEvery : position.every;
    if (restored && every != position.every) {
      position.checkpoint = 1;
      while (every > 0.0 && dtss::gridOffset(every, position.checkpoint) <= restart.t) ++position.checkpoint;
    }
    position.every = every;
    for (;;) {
      // (events up to the next sample or checkpoint time) => executed, then the row, the
      // checkpoint
      const double recordAt =
          recorder ? std::min(dtss::gridOffset(interval, position.record), opt.until) : opt.until;
      const double checkpointAt =
          every > 0.0 ? dtss::gridOffset(every, position.checkpoint) : devs::kInfinity;
      const double next = std::min(recordAt, checkpointAt);
      std::size_t steps = 0;
      while (sim.nextEventTime() <= next) {
        try {
          sim.step();
        } catch (const devs::SimulationError&) {
          // (a model that failed at the record time) => its last valid state, committed at that
          // time before the step that failed (dtss/atomic.hpp: look-ahead), is the last row
          if (recorder && next == recordAt && sim.time() == next) {
            recorder->sample(next);
            reached = next;
          }
          throw;
        }
        if (++steps % 64 == 0) report(sim.time());
      }
      if (std::isinf(next)) break;  // until no event is left
      sim.runUntil(next);
      if (next == recordAt) {
        output([&] {
          if (recorder) recorder->sample(next);
          if (replaying && (position.record % stride == 0 || next >= opt.until)) replay.sample(next);
        });
        ++position.record;
        reached = next;
        report(next);
      }
      if (next == checkpointAt) {
        ++position.checkpoint;
        if (next < opt.until) checkpoint(next);
      }
      if (next >= opt.until) break;
      if (std::isinf(opt.until) && sim.nextEventTime() == devs::kInfinity) break;
    }
    // (sinks) => their last chunks written and their files closed, booked as output as their
    // opening is (the simulator calls none of them after the last step)
    output([&] {
      timed.reset();
      filters.clear();
      sinks.clear();
    });
    result.tEnd = sim.time();
    result.wall = wall();
    result.samples = recorder ? recorder->rows() : 0;
    result.stats = sim.stats();
    result.alarms = alarms.alarms();
    raiseToRopePeaks(result.alarms, root);
    if (opt.progress) opt.progress({result.tEnd, opt.until, result.wall});
    reached = sim.time();
  } catch (const devs::CheckpointError&) {
    throw;  // nothing was simulated: the caller says why (exit 1)
  } catch (const std::exception& e) {
    facts.status = "failed";
    facts.message = e.what();
    finish();
    throw;
  }
  finish();
  result.outputSeconds = outputSeconds;
  result.simulateSeconds = wall() - outputSeconds;
  return result;
}

}  // namespace yardsim::run
