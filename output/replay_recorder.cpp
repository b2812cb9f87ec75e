#include "output/replay_recorder.hpp"

namespace yardsim::output {

using models::Replayable;

ReplayRecorder::ReplayRecorder(const devs::Model& root) {
  // (model tree) => every Replayable atomic, in order, with its bodies and ropes
  std::vector<const devs::Model*> stack{&root};
  while (!stack.empty()) {
    const devs::Model* m = stack.back();
    stack.pop_back();
    if (!m->isAtomic()) {
      const auto& kids = static_cast<const devs::Coupled*>(m)->components();
      for (auto it = kids.rbegin(); it != kids.rend(); ++it) stack.push_back(it->get());
    } else if (const auto* r = dynamic_cast<const Replayable*>(m)) {
      sources_.emplace_back(r, replay_.bodies.size());
      r->replayBodies(replay_);
    }
  }
}

void ReplayRecorder::sample(double t) {
  if (empty()) return;
  replay_.times.push_back(static_cast<float>(t));
  for (const auto& [r, first] : sources_) r->replayFrame(replay_, first);
}

}  // namespace yardsim::output
