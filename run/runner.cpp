#include "run/runner.hpp"

#include <chrono>
#include <cmath>
#include <memory>

#include "devs/chrome_trace_sink.hpp"
#include "devs/csv_trace_sink.hpp"
#include "devs/jsonl_trace_sink.hpp"
#include "dtss/grid.hpp"
#include "models/channels.hpp"
#include "output/gltf_writer.hpp"
#include "output/replay_recorder.hpp"
#include "run/run_summary.hpp"
#include "run/timeseries_writer.hpp"

namespace yardsim::run {

using models::collectChannels;
using models::selectChannels;
using output::ReplayRecorder;
using output::writeGlb;
using scene::Scene;

RunResult runScene(const Scene& scene, devs::Coupled& root, const RunOptions& opt) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto wall = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  std::filesystem::create_directories(opt.outdir);

  // (record block) => the recorder, only when the scene asks for one
  std::unique_ptr<TimeseriesWriter> recorder;
  const double interval = scene.record.interval;
  if (interval > 0.0)
    recorder = std::make_unique<TimeseriesWriter>(
        opt.outdir / "timeseries.csv", scene,
        selectChannels(collectChannels(root), scene.record.channels));
  // (initial state) => the first row, on disk before the simulator computes its first step (a
  // step that fails at once still leaves it)
  if (recorder) recorder->sample(0.0);

  // (record grid, frame budget) => replay frames every `stride` samples, from the same t = 0
  ReplayRecorder replay(root);
  std::int64_t stride = 1;
  if (interval > 0.0 && std::isfinite(opt.until) && opt.maxReplayFrames > 0)
    stride = std::max<std::int64_t>(
        1, static_cast<std::int64_t>(std::ceil(opt.until / interval / static_cast<double>(opt.maxReplayFrames))));
  const bool replaying = recorder && !replay.empty();
  if (replaying) replay.sample(0.0);
  AlarmMonitor alarms(opt.onAlarm);
  RunFacts facts;
  facts.until = opt.until;
  facts.replayInterval = replaying ? interval * static_cast<double>(stride) : 0.0;
  double reached = 0.0;  // simulated time, s
  // (facts) => replay.glb and run.json, also when the run fails
  auto finish = [&] {
    facts.tEnd = reached;
    facts.alarms = alarms.alarms();
    facts.wall = wall();
    if (replaying) writeGlb(replay.replay(), opt.outdir / "replay.glb");
    writeRunSummary(opt.outdir / "run.json", scene, root, facts);
  };

  RunResult result;
  try {
    devs::Simulator sim(root);
    sim.setInstantLimit(opt.maxTransitionsPerInstant);
    // (trace names) => sinks, only those asked for
    std::vector<std::unique_ptr<devs::Listener>> sinks;
    for (const auto& name : opt.trace) {
      if (name == "jsonl")
        sinks.push_back(std::make_unique<devs::JsonlTraceSink>(devs::TraceStream(opt.outdir / "trace.jsonl")));
      else if (name == "chrome")
        sinks.push_back(std::make_unique<devs::ChromeTraceSink>(devs::TraceStream(opt.outdir / "trace.json")));
      else if (name == "csv")
        sinks.push_back(std::make_unique<devs::CsvTraceSink>(devs::TraceStream(opt.outdir / "trace.csv")));
      else
        throw std::invalid_argument("unknown trace sink '" + name + "' (expected jsonl, chrome or csv)");
      sim.addListener(*sinks.back());
    }
    sim.addListener(alarms);
    double lastReport = 0.0;
    auto report = [&](double t) {
      if (!opt.progress) return;
      const double w = wall();
      if (w - lastReport < opt.progressPeriod) return;
      lastReport = w;
      opt.progress({t, opt.until, w});
    };
    for (std::int64_t k = 1;; ++k) {
      // (events up to the next sample time) => executed, then one row
      const double next = recorder ? std::min(dtss::gridOffset(interval, k), opt.until) : opt.until;
      std::size_t steps = 0;
      while (sim.nextEventTime() <= next) {
        sim.step();
        if (++steps % 64 == 0) report(sim.time());
      }
      if (std::isinf(next)) break;  // until no event is left
      sim.runUntil(next);
      if (recorder) recorder->sample(next);
      if (replaying && (k % stride == 0 || next >= opt.until)) replay.sample(next);
      reached = next;
      report(next);
      if (next >= opt.until) break;
      if (std::isinf(opt.until) && sim.nextEventTime() == devs::kInfinity) break;
    }
    result.tEnd = sim.time();
    result.wall = wall();
    result.samples = recorder ? recorder->rows() : 0;
    result.stats = sim.stats();
    result.alarms = alarms.alarms();
    if (opt.progress) opt.progress({result.tEnd, opt.until, result.wall});
    reached = sim.time();
  } catch (const std::exception& e) {
    facts.status = "failed";
    facts.message = e.what();
    finish();
    throw;
  }
  finish();
  return result;
}

}  // namespace yardsim::run
