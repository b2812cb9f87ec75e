// The report's trace (run/event_trace.hpp): the `events` sink writes exactly the output records
// of the full `jsonl` trace (actor started/finished, the multibody model's events, set-points),
// in the same order and form, and none of its per-step int/state/in records; asked together with
// `jsonl`, the full trace is written alone.
#include "run/event_trace.hpp"

#include <catch2/catch.hpp>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "run/runner.hpp"
#include "scene/assembler.hpp"
#include "scene/scene_loader.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;

namespace {
// a block hanging from a rope, hauled in 0.1 m by a wire actor from t = 0.5 s
const char* kScene = R"(schema_version: 1
integrator: {method: rk4, dt: 0.002}
until: 3
record: {interval: 0.01}
components:
  haul: {type: wire_actor, params: {rope: hoist, payout: -0.1, speed: 0.1, start_at: 0.5}}
mechanics:
  bodies:
    block:
      parent: world
      joint: {type: prismatic, axis: [0, 0, 1], q0: -10.001}
      mass: 1000.0
      inertia: [100, 100, 100]
  ropes:
    hoist:
      path: [{body: world, point: [0, 0, 0]}, {body: block, point: [0, 0, 0]}]
      EA: 1.0e8
      L0: 10.0
      damping: 2.0e5
)";

// (trace.jsonl) => its lines without the sequence number (the two sinks number differently)
std::vector<std::string> lines(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::vector<std::string> out;
  const std::regex seq(",\"seq\":[0-9]+");
  for (std::string l; std::getline(in, l);) out.push_back(std::regex_replace(l, seq, ""));
  return out;
}

std::vector<std::string> traceOf(const testing::SceneDir& dir, const std::string& name,
                                 std::vector<std::string> sinks) {
  auto scene = scene::loadSceneOrThrow(dir.path() / "s.yaml");
  auto root = scene::assemble(*scene);
  run::RunOptions opt{dir.path() / name, scene->until, std::move(sinks), {}, 0.1, 2000};
  run::runScene(*scene, *root, opt);
  return lines(dir.path() / name / "trace.jsonl");
}
}  // namespace

TEST_CASE("the events trace is the full trace's output records and nothing else") {
  testing::SceneDir dir;
  dir.write("s.yaml", kScene);
  const auto full = traceOf(dir, "full", {"jsonl"});
  const auto events = traceOf(dir, "events", {"events"});
  std::vector<std::string> outputs;
  for (const auto& l : full)
    if (l.find("\"kind\":\"out\"") != std::string::npos) outputs.push_back(l);
  CHECK(events == outputs);
  CHECK(full.size() > 10 * events.size());  // the per-step records are the bulk
  // (what the report reads) => the actor's span and the winch's end are in it
  auto has = [&](const std::string& what) {
    for (const auto& l : events)
      if (l.find(what) != std::string::npos) return true;
    return false;
  };
  CHECK(has("\"model\":\"haul\",\"kind\":\"out\",\"port\":\"started\""));
  CHECK(has("\"model\":\"haul\",\"kind\":\"out\",\"port\":\"finished\""));
  CHECK(has("\"port\":\"event\",\"value\":\"hoist done"));
  // (both asked) => the full trace, once
  CHECK(traceOf(dir, "both", {"events", "jsonl"}) == full);
}
