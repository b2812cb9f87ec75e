#include "models/runner.hpp"

#include <chrono>
#include <cmath>
#include <memory>

#include "devs/chrome_trace_sink.hpp"
#include "devs/csv_trace_sink.hpp"
#include "devs/jsonl_trace_sink.hpp"
#include "dtss/grid.hpp"
#include "models/channels.hpp"
#include "models/timeseries_writer.hpp"

namespace yardsim::models {

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

  devs::Simulator sim(root);
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
  RunResult result;
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
    report(next);
    if (next >= opt.until) break;
    if (std::isinf(opt.until) && sim.nextEventTime() == devs::kInfinity) break;
  }
  result.tEnd = sim.time();
  result.wall = wall();
  result.samples = recorder ? recorder->rows() : 0;
  result.stats = sim.stats();
  if (opt.progress) opt.progress({result.tEnd, opt.until, result.wall});
  return result;
}

}  // namespace yardsim::models
