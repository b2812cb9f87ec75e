#pragma once
// Samples the poses of every Replayable model below a root into a Replay (for replay.glb and
// the report's 3D view).
#include <vector>

#include "devs/coupled.hpp"
#include "models/replay.hpp"

namespace yardsim::output {

using models::Replay;
using models::Replayable;

class ReplayRecorder {
 public:
  explicit ReplayRecorder(const devs::Model& root);
  bool empty() const { return replay_.bodies.empty(); }
  // (t) => one frame: every body's pose now
  void sample(double t);
  const Replay& replay() const { return replay_; }

 private:
  std::vector<std::pair<const Replayable*, std::size_t>> sources_;  // (model, first body)
  Replay replay_;
};

}  // namespace yardsim::output
