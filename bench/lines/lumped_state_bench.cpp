// Lumped-mass lines stepped in the multibody state (issue 17: 8 lines x 20 segments with the
// scene's implicit integrator at >= 20x real time at a 0.05 s step; the cost per step against the
// number of nodes): a 200 t buoy on a surge-sway slider at the fairlead height, moored by 8 chain
// lines of n segments in still water and released at 0.5 m/s in surge, run as a scene (scene
// loader, assembler, runner; one channel recorded every 10 s) for 20 s of simulated time, and
// again for 10 s: the difference is the second half, after the release's transient ("_late").
// Counters: real-time factor and wall time per step and per inner node (wall time: on a shared
// machine compare the CPU column too); and the integrator's work per step (stage evaluations,
// Jacobians, Newton iterations, factorisations) with its failed Newton solves and error-test
// failures, the factors of the cost besides the nodes. The "Suspended" cases are the same scene
// without a sea bed (seabed: false): the chains hang below their anchors and never touch a bed,
// so only the segments' slack/taut corner can switch. A run includes the run summary's stiffness
// estimate (Arnoldi on the coloured Jacobian for a system with lumped lines:
// mechanics/largest_mode.hpp).
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "dynamics/integrators/adaptive_integrator.hpp"
#include "models/multibody/multibody_model.hpp"
#include "run/runner.hpp"
#include "scene/assembler.hpp"
#include "scene/scene_loader.hpp"

using namespace yardsim;
namespace fs = std::filesystem;

namespace {

constexpr double kUntil = 20.0, kStep = 0.05;

// (segments per line, integrator, whether the lines lie on a sea bed) => the scene: 8 lines
// spread at 45 deg, 290 m out, 39 m down (without the bed, hanging below their anchors)
std::string scene(int segments, const std::string& method, bool bed = true) {
  std::string s = "schema_version: 1\nintegrator: {method: " + method +
                  ", dt: " + std::to_string(kStep) + ", stiffness_check: off}\n" + R"(mechanics:
  gravity: [0, 0, 0]
  bodies:
    slide_x: {parent: world, joint: {type: prismatic, axis: [1, 0, 0], v0: 0.5}, mass: 1.0,
              inertia: [1, 1, 1]}
    buoy: {parent: slide_x, joint: {type: prismatic, axis: [0, 1, 0]},
           placement: {xyz: [0, 0, 39]}, mass: 2.0e5, inertia: [1, 1, 1]}
  mooring:
)";
  for (int k = 0; k < 8; ++k) {
    const double a = k * M_PI / 4.0;
    s += "    line" + std::to_string(k) + ": {model: lumped, anchor: [" +
         std::to_string(290.0 * std::cos(a)) + ", " + std::to_string(290.0 * std::sin(a)) +
         ", 0], fairlead: {body: buoy}, length: 314, EA: 1.2e9, mass: 282.21, diameter: "
         "0.216, segments: " +
         std::to_string(segments) + (bed ? "}\n" : ", seabed: false}\n");
  }
  return s + "record: {interval: 10, channels: [\"line0.fairlead_tension\"]}\nuntil: " +
         std::to_string(kUntil) + "\n";
}

// (model tree) => its (first) multibody model, or nullptr
const models::MultibodyModel* multibody(const devs::Model& m) {
  if (const auto* mb = dynamic_cast<const models::MultibodyModel*>(&m)) return mb;
  if (m.isAtomic()) return nullptr;
  for (const auto& c : static_cast<const devs::Coupled&>(m).components())
    if (const auto* s = multibody(*c)) return s;
  return nullptr;
}

// (model tree) => the integrator's work of its (first) multibody model, or nullptr
const dynamics::IntegratorStats* integratorStats(const devs::Model& m) {
  const auto* mb = multibody(m);
  return mb ? &mb->integratorStats() : nullptr;
}

// (scene, until, SUNDIALS' dense Newton instead of the chart Newton system) => wall time of one
// whole run and its integrator's work
double runOnce(const scene::Scene& loaded, const fs::path& out, double until,
               dynamics::IntegratorStats& work, bool dense = false) {
  auto root = scene::assemble(loaded);
  if (dense) {
    // (the model's adaptive integrator, before its first step) => the dense path (the bench's
    // "before"; the model hands out its integrator const only)
    const auto* mb = multibody(*root);
    const auto* adaptive =
        mb ? dynamic_cast<const dynamics::AdaptiveIntegrator*>(&mb->integrator()) : nullptr;
    if (adaptive == nullptr) throw std::runtime_error("no adaptive integrator to make dense");
    const_cast<dynamics::AdaptiveIntegrator*>(adaptive)->useDenseNewton(true);
  }
  const auto t0 = std::chrono::steady_clock::now();
  run::runScene(loaded, *root, {out, until, {}, {}, 0.1});
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (const auto* s = integratorStats(*root)) work = *s;
  return wall;
}

// (state.range(0): segments; method) => per iteration one whole run, and one to half its length:
// their difference is the second half, after the buoy's release (the "_late" counters)
void runLines(benchmark::State& state, const std::string& method, bool dense = false,
              bool bed = true) {
  const int segments = static_cast<int>(state.range(0));
  const fs::path dir =
      fs::temp_directory_path() /
      ("yardsim-bench-lines-" + method + (bed ? "" : "-suspended") + std::to_string(segments));
  fs::create_directories(dir);
  std::ofstream(dir / "s.yaml") << scene(segments, method, bed);
  auto loaded = scene::loadSceneOrThrow(dir / "s.yaml");
  double wall = 0.0, wallHalf = 0.0;
  dynamics::IntegratorStats work, half;
  for (auto _ : state) {
    wall += runOnce(*loaded, dir / "out", kUntil, work, dense);
    wallHalf += runOnce(*loaded, dir / "out", 0.5 * kUntil, half, dense);
  }
  const double runs = static_cast<double>(state.iterations()), steps = kUntil / kStep;
  const double nodes = 8.0 * (segments - 1);
  state.counters["realtime_factor"] = kUntil * runs / wall;
  state.counters["us_per_step"] = 1e6 * wall / runs / steps;
  state.counters["ns_per_step_node"] = 1e9 * wall / runs / steps / nodes;
  // (the last run's integrator work) => per step of the grid: stage evaluations, Jacobians,
  // Newton iterations and failed solves (the cost's factors besides the nodes)
  state.counters["solver_steps_per_step"] = static_cast<double>(work.steps) / steps;
  state.counters["f_evals_per_step"] = static_cast<double>(work.f_evals) / steps;
  state.counters["jacobians_per_step"] = static_cast<double>(work.jac_evals) / steps;
  state.counters["newton_per_step"] = static_cast<double>(work.newton_its) / steps;
  state.counters["failed_solves"] = static_cast<double>(work.err_fails);
  state.counters["factorisations_per_step"] = static_cast<double>(work.factorisations) / steps;
  state.counters["conv_fails"] = static_cast<double>(work.conv_fails);
  // (whole run - half run) => the same for the second half alone
  const double late = 0.5 * steps;
  state.counters["us_per_step_late"] = 1e6 * (wall - wallHalf) / runs / late;
  state.counters["f_evals_per_step_late"] = static_cast<double>(work.f_evals - half.f_evals) / late;
  state.counters["newton_per_step_late"] =
      static_cast<double>(work.newton_its - half.newton_its) / late;
  state.counters["failed_solves_late"] = static_cast<double>(work.err_fails - half.err_fails);
  state.counters["solver_steps_per_step_late"] =
      static_cast<double>(work.steps - half.steps) / late;
  state.counters["jacobians_per_step_late"] =
      static_cast<double>(work.jac_evals - half.jac_evals) / late;
  state.counters["factorisations_per_step_late"] =
      static_cast<double>(work.factorisations - half.factorisations) / late;
  state.counters["conv_fails_late"] = static_cast<double>(work.conv_fails - half.conv_fails);
  fs::remove_all(dir);
}

void BM_LumpedLinesHht(benchmark::State& state) {
  runLines(state, "hht");
}
BENCHMARK(BM_LumpedLinesHht)
    ->Arg(5)
    ->Arg(10)
    ->Arg(20)
    ->Arg(40)
    ->Arg(80)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

// CVODE BDF with the chart Newton system (sparse, the default with lumped lines), and with
// SUNDIALS' dense difference-quotient Jacobian and dense LU (the path before 2026-11-29)
void BM_LumpedLinesCvode(benchmark::State& state) {
  runLines(state, "cvode_bdf");
}
BENCHMARK(BM_LumpedLinesCvode)
    ->Arg(10)
    ->Arg(20)
    ->Arg(40)
    ->Arg(80)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

void BM_LumpedLinesCvodeDense(benchmark::State& state) {
  runLines(state, "cvode_bdf", true);
}
BENCHMARK(BM_LumpedLinesCvodeDense)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond)->Iterations(1);

// The same lines without a sea bed (fully suspended: nothing touches down), HHT and CVODE BDF
void BM_LumpedLinesSuspendedHht(benchmark::State& state) {
  runLines(state, "hht", false, false);
}
BENCHMARK(BM_LumpedLinesSuspendedHht)
    ->Arg(10)
    ->Arg(20)
    ->Arg(40)
    ->Arg(80)
    ->Arg(160)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

void BM_LumpedLinesSuspendedCvode(benchmark::State& state) {
  runLines(state, "cvode_bdf", false, false);
}
BENCHMARK(BM_LumpedLinesSuspendedCvode)
    ->Arg(10)
    ->Arg(20)
    ->Arg(40)
    ->Arg(80)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
