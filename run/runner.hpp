#pragma once
// Running an assembled scene: trace sinks and the time-series recorder are attached only when
// asked for, samples are taken on the record grid (after every event at that time), progress
// is reported to a callback, and whatever was recorded is on disk if the run throws.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "devs/coupled.hpp"
#include "devs/simulator.hpp"
#include "models/diagnostics.hpp"
#include "run/alarms.hpp"
#include "scene/scene.hpp"

namespace yardsim::run {

using scene::Scene;

struct Progress {
  double t;       // simulated time reached, s
  double until;   // end time, s (infinite when the scene runs until no event is left)
  double wall;    // wall time so far, s
};

struct RunOptions {
  std::filesystem::path outdir;
  double until;                     // end time, s
  std::vector<std::string>
      trace;  // sinks: jsonl (trace.jsonl), events (trace.jsonl, outputs
              // only: run/event_trace.hpp), chrome (trace.json), csv (trace.csv)
  std::function<void(const Progress&)> progress;  // called at most every progressPeriod
  double progressPeriod = 0.1;      // s of wall time
  std::size_t maxReplayFrames = 2000;  // replay.glb takes every k-th sample so as to stay below
  std::function<void(const Alarm&)> onAlarm = {};  // at the first occurrence of each alarm or notice
  // the warnings of the scene's validation (the stiffness guard's and the others the run
  // printed), each one `warning` of the run's alarms from its start time (run/alarms.hpp)
  std::vector<models::Diagnostic> warnings = {};
  // more transitions than this at one simulated time stop the run (devs::Simulator::setInstantLimit)
  std::uint64_t maxTransitionsPerInstant = 1000000;
  // checkpoints (docs/scenes.md): every this many simulated seconds (0: none), written to
  // OUTDIR/checkpoints/t000050.000.ckpt after every event up to that time
  double checkpointEvery = 0.0;
  // a checkpoint of this scene to continue from (empty: start at t = 0); OUTDIR then holds the
  // rows, trace records and replay frames after the checkpoint's time
  std::filesystem::path restartFrom = {};
  // time the trace sinks' hooks too (RunResult::outputSeconds); costs two clock reads per hook
  bool profile = false;
};

struct RunResult {
  double tEnd = 0.0;
  double wall = 0.0;
  std::size_t samples = 0;
  devs::SimulatorStats stats;
  std::vector<Alarm> alarms;  // every safety event of the run (alarms.hpp), also in run.json
  // wall s of writing output inside runScene (CSV rows, replay frames, replay.glb, run.json, and
  // with RunOptions::profile the trace sinks), and of the rest (simulator set-up and events)
  double outputSeconds = 0.0;
  double simulateSeconds = 0.0;
};

// (scene, its assembled model, options) => the run: OUTDIR/timeseries.csv and the traces asked
// for, OUTDIR/replay.glb (the bodies' poses on the record grid) when the scene has bodies and
// records, and OUTDIR/run.json; throws what the simulation throws, after writing what it has.
// A checkpoint that cannot be applied (another scene or version, a damaged file, a model type
// without a state codec) throws devs::CheckpointError before anything is simulated.
RunResult runScene(const Scene& scene, devs::Coupled& root, const RunOptions& options);

}  // namespace yardsim::run
