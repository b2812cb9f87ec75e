#pragma once
// OUTDIR/report.html (docs/report.md): one self-contained page built from what a run left in
// OUTDIR — timeseries.csv (plots), run.json (header, the scene's `report:` block), trace.jsonl
// (actor timeline) and replay.glb (3D replay) — with the report bundle (report/, embedded in
// the binary) inlined. Arrays travel as base64 float32, replay.glb as base64 bytes.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "output/timeseries_reader.hpp"

namespace yardsim::output {

struct RopePeak {
  std::string channel;                 // "<rope>.tension"
  double peak = 0.0, time = 0.0;       // N, s
  std::optional<double> staticValue;   // N, from the scene's report.static
  double ratio() const { return staticValue && *staticValue != 0 ? peak / *staticValue : 0.0; }
};

// (time series, static levels) => the peak of every tension channel (name ending in
// ".tension") and its ratio to the static value where one is given; where the rope's running
// maximum "<rope>.peak_tension" is recorded too, its final value (the peak over every step)
std::vector<RopePeak> ropePeaks(const Timeseries& ts,
                                const std::vector<std::pair<std::string, double>>& staticLevels);

struct ActorSpan {
  std::string path, kind;
  double start = -1.0, end = -1.0;  // s; -1: never started / not finished
};

// (trace.jsonl, actors from run.json) => each actor's start and finish from its `started` and
// `finished` outputs; actors that appear in the trace only are added with kind "actor"
std::vector<ActorSpan> actorSpans(const std::filesystem::path& traceJsonl, std::vector<ActorSpan> actors);

// (OUTDIR) => OUTDIR/report.html; throws std::runtime_error naming what is missing or bad
void writeReport(const std::filesystem::path& outdir);

}  // namespace yardsim::output
