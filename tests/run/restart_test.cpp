// Restarts (run/runner.cpp with --restart): a run continued from a checkpoint, its rows and its
// trace appended to those of the run that wrote it up to the checkpoint's time, equals that run
// bit for bit. On the goliath turnover (in the middle of the turnover, winches running), the
// floating barge (hydrostatics, waves, wind), the barge under CVODE (adaptive, with a history), a
// buoy on lumped lines and a block hoisted on a rope with mass (its winch in the state).
#include <catch2/catch.hpp>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "run/runner.hpp"
#include "scene/assembler.hpp"
#include "scene/scene_loader.hpp"
#include "support/scene_files.hpp"
#include "support/test_paths.hpp"

using namespace yardsim;
namespace fs = std::filesystem;

namespace {
const fs::path kExamples = fs::path(YARDSIM_SOURCE_DIR) / "examples";

struct Output {
  std::vector<std::string> rows;   // timeseries.csv below its header
  std::vector<std::string> trace;  // trace.jsonl
};

// (line of trace.jsonl or row of timeseries.csv) => its time, s
double timeOf(const std::string& line) {
  return std::stod(line.front() == '{' ? line.substr(5) : line);
}

// (scene, output folder, checkpoint period, checkpoint to restart from) => what the run wrote
Output runScene(const fs::path& file, const fs::path& out, double every,
                const fs::path& restart = {}) {
  auto scene = scene::loadSceneOrThrow(file);
  auto root = scene::assemble(*scene);
  run::RunOptions opt{out, scene->until, {"jsonl"}, {}, 0.1, 2000};
  opt.checkpointEvery = every;
  opt.restartFrom = restart;
  run::runScene(*scene, *root, opt);
  Output o;
  std::ifstream csv(out / "timeseries.csv");
  for (std::string l; std::getline(csv, l);)
    if (l.front() != '#' && l.rfind("time[s]", 0) != 0) o.rows.push_back(l);
  std::ifstream jsonl(out / "trace.jsonl");
  for (std::string l; std::getline(jsonl, l);) o.trace.push_back(l);
  return o;
}

// (whole run, its part up to t, the restarted run) => whole == part + restarted
void checkConcatenation(const Output& whole, const Output& restarted, double t) {
  std::vector<std::string> rows, trace;
  for (const auto& r : whole.rows)
    if (timeOf(r) <= t) rows.push_back(r);
  for (const auto& r : whole.trace)
    if (timeOf(r) <= t) trace.push_back(r);
  REQUIRE(rows.size() < whole.rows.size());
  REQUIRE(!restarted.rows.empty());
  CHECK(timeOf(restarted.rows.front()) > t);
  rows.insert(rows.end(), restarted.rows.begin(), restarted.rows.end());
  trace.insert(trace.end(), restarted.trace.begin(), restarted.trace.end());
  CHECK(rows.size() == whole.rows.size());
  CHECK(rows == whole.rows);
  CHECK(trace.size() == whole.trace.size());
  CHECK(trace == whole.trace);
}

// (trace, actor, port) => the time of the actor's first message on that port, or -1
double actorTime(const Output& o, const std::string& actor, const std::string& port) {
  for (const auto& l : o.trace)
    if (l.find("\"kind\":\"out\"") != std::string::npos &&
        l.find("\"port\":\"" + port + "\"") != std::string::npos &&
        (l.find("\"model\":\"" + actor + "\"") != std::string::npos ||
         l.find("." + actor + "\"") != std::string::npos))
      return timeOf(l);
  return -1.0;
}
}  // namespace

TEST_CASE("the goliath turnover restarted in the middle of the turnover equals the whole run",
          "[long]") {
  testing::SceneDir dir;
  const fs::path scene = kExamples / "goliath_turnover/scene.yaml";
  const Output whole = runScene(scene, dir.path() / "whole", 50.0);
  // (trace) => at t = 300 s the turnover's wire actors are running: their winches pay out
  const double started = actorTime(whole, "turn1", "started");
  const double finished = actorTime(whole, "turn1", "finished");
  INFO("turn1 runs from " << started << " s to " << finished << " s");
  REQUIRE(started > 0.0);
  REQUIRE(started < 300.0);
  REQUIRE(finished > 300.0);
  const Output restarted = runScene(scene, dir.path() / "restarted", 0.0,
                                    dir.path() / "whole/checkpoints/t000300.000.ckpt");
  checkConcatenation(whole, restarted, 300.0);
  // (RK4 has no history) => writing checkpoints changes nothing: a run without them is the same
  const Output plain = runScene(scene, dir.path() / "plain", 0.0);
  CHECK(plain.rows == whole.rows);
  CHECK(plain.trace == whole.trace);
  // (the restarted run) => writes the later checkpoints of the same period itself
  CHECK(fs::exists(dir.path() / "restarted/checkpoints/t000350.000.ckpt"));
  CHECK_FALSE(fs::exists(dir.path() / "restarted/checkpoints/t000300.000.ckpt"));
}

TEST_CASE("the floating barge restarted in waves equals the whole run", "[long]") {
  testing::SceneDir dir;
  const fs::path scene = kExamples / "floating_barge/scene.yaml";
  const Output whole = runScene(scene, dir.path() / "whole", 35.0);
  const Output restarted = runScene(scene, dir.path() / "restarted", 0.0,
                                    dir.path() / "whole/checkpoints/t000070.000.ckpt");
  checkConcatenation(whole, restarted, 70.0);
}

TEST_CASE("an adaptive CVODE scene restarted from a checkpoint equals the run that wrote it") {
  testing::SceneDir dir;
  // (the floating barge under CVODE BDF, 0.05 s grid) => its file beside the example's hull
  std::ifstream in(kExamples / "floating_barge/scene.yaml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string rk4 = "integrator: {method: rk4, dt: 0.01}";
  REQUIRE(text.find(rk4) != std::string::npos);
  text.replace(text.find(rk4), rk4.size(), "integrator: {method: cvode_bdf, dt: 0.05}");
  REQUIRE(text.find("\nuntil:") != std::string::npos);
  text.replace(text.find("\nuntil:"), 7, "\nuntil: 100 #");
  fs::copy_file(kExamples / "floating_barge/barge_hull.obj", dir.path() / "barge_hull.obj");
  const fs::path scene = dir.write("cvode.yaml", text);
  const Output whole = runScene(scene, dir.path() / "whole", 20.0);
  const Output restarted = runScene(scene, dir.path() / "restarted", 0.0,
                                    dir.path() / "whole/checkpoints/t000060.000.ckpt");
  checkConcatenation(whole, restarted, 60.0);
}

TEST_CASE("the moored barge restarted in waves equals the whole run (the catenaries' warm start)",
          "[long]") {
  testing::SceneDir dir;
  const fs::path scene = kExamples / "moored_barge/scene.yaml";
  const Output whole = runScene(scene, dir.path() / "whole", 35.0);
  const Output restarted = runScene(scene, dir.path() / "restarted", 0.0,
                                    dir.path() / "whole/checkpoints/t000070.000.ckpt");
  checkConcatenation(whole, restarted, 70.0);
}

TEST_CASE("a buoy on lumped mooring lines restarted mid-swing equals the whole run (nodes in q, v)",
          "[long]") {
  // (two lumped lines of 10 segments: their 18 inner nodes are bodies, so their positions and
  // velocities are part of the multibody state's q and v and of its checkpoint) => under CVODE
  // BDF. (Under HHT the restarted run differs in the last digit: the whole run keeps reusing
  // its Newton matrix across the checkpoint, the restarted one forms a fresh one; docs/lines.md.)
  testing::SceneDir dir;
  const std::string line = "length: 314, EA: 1.2e9, mass: 282.21, diameter: 0.216, segments: 10";
  const fs::path scene = dir.write("lumped.yaml", R"(schema_version: 1
integrator: {method: cvode_bdf, dt: 0.05}
mechanics:
  gravity: [0, 0, -9.81]
  bodies:
    buoy:
      parent: world
      joint: {type: prismatic, axis: [1, 0, 0], v0: 1.0}
      placement: {xyz: [0, 0, 39]}
      mass: 2.0e5
      inertia: [1, 1, 1]
  mooring:
    west: {model: lumped, anchor: [-300, 0, 0], fairlead: {body: buoy}, )" +
                                                      line + R"(}
    east: {model: lumped, anchor: [300, 0, 0], fairlead: {body: buoy}, )" +
                                                      line + R"(}
record: {interval: 0.1, channels: ["buoy.x", "west.*", "east.*", "mechanics.energy_balance"]}
until: 20
)");
  const Output whole = runScene(scene, dir.path() / "whole", 5.0);
  const Output restarted = runScene(scene, dir.path() / "restarted", 0.0,
                                    dir.path() / "whole/checkpoints/t000010.000.ckpt");
  checkConcatenation(whole, restarted, 10.0);
}

TEST_CASE(
    "a block hoisted on a rope with mass restarted mid-hoist equals the whole run (its winch)") {
  // (a lumped crane rope whose winch hauls in: the winch's pieces are in the multibody state after
  // the ropes', and a restarted run takes them back; without them it would hang at rest)
  testing::SceneDir dir;
  const fs::path scene = dir.write("hoist.yaml", R"(schema_version: 1
integrator: {method: rk4, dt: 0.0005}
components:
  up: {type: wire_actor, params: {rope: hoist, payout: -3, speed: 1, accel: 0.5, start_at: 0.5}}
mechanics:
  bodies:
    top: {parent: world, joint: {type: fixed}, placement: {xyz: [0, 0, 30]}, mass: 1000, inertia: [1, 1, 1]}
    block: {parent: world, joint: {name: lift, type: prismatic, axis: [0, 0, 1], q0: 9.99},
            mass: 2000, inertia: [100, 100, 100]}
  ropes:
    hoist: {model: lumped, path: [{body: top}, {body: block}], L0: 20, segments: 8, EA: 5.0e7,
            mass_per_length: 10, diameter: 0.04}
record: {interval: 0.01, channels: ["hoist.*", "lift.q", "mechanics.energy_balance"]}
until: 4
)");
  const Output whole = runScene(scene, dir.path() / "whole", 1.0);
  const Output restarted = runScene(scene, dir.path() / "restarted", 0.0,
                                    dir.path() / "whole/checkpoints/t000002.000.ckpt");
  checkConcatenation(whole, restarted, 2.0);
}
