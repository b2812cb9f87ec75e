#pragma once
// OUTDIR/run.json: what the report's header needs and the run's other outputs do not say —
// scene name and file, the integrator and step of each multibody model, simulated and wall
// time, how the run ended, the actors (path and kind), the scene's `report:` block, per rope its
// peak, static and breaking loads (`ropes`) and the safety events of the run (`alarms`).
// Written when a run ends, and when it fails.
#include <filesystem>
#include <string>

#include <vector>

#include "devs/coupled.hpp"
#include "run/alarms.hpp"
#include "scene/scene.hpp"

namespace yardsim::run {

using scene::Scene;

struct RunFacts {
  double until = 0.0, tEnd = 0.0, wall = 0.0;  // s
  std::string status = "ok";                   // ok | failed
  std::string message;                         // the diagnosis when failed
  double replayInterval = 0.0;                 // s between replay frames; 0: no replay
  std::vector<Alarm> alarms;                   // in order of first occurrence
};

// (scene, its assembled model, facts) => run.json text
std::string runSummaryJson(const Scene& scene, const devs::Model& root, const RunFacts& facts);
// (file, ...) => written; throws std::runtime_error naming the file when it cannot be
void writeRunSummary(const std::filesystem::path& file, const Scene& scene,
                     const devs::Model& root, const RunFacts& facts);

}  // namespace yardsim::run
