#pragma once
// Test support: run a scene written as text to its end and read its timeseries.csv back.
#include <string>

#include "run/runner.hpp"
#include "scene/assembler.hpp"
#include "scene/scene_loader.hpp"
#include "support/csv_file.hpp"
#include "support/scene_files.hpp"

namespace yardsim::testing {

// (folder, scene text, until in s) => the scene run from dir/s.yaml into dir/out: its
// timeseries.csv
inline CsvFile simulateScene(const SceneDir& dir, const std::string& text, double until) {
  auto scene = scene::loadSceneOrThrow(dir.write("s.yaml", text));
  auto root = scene::assemble(*scene);
  run::runScene(*scene, *root, {dir.path() / "out", until, {}, {}, 0.1});
  return CsvFile((dir.path() / "out" / "timeseries.csv").string());
}

}  // namespace yardsim::testing
