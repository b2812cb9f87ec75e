// The time-domain Rankine-panel solver at the issue's size: a floating hemisphere of radius 10 m
// (cube sphere n = 18: 972 wetted panels, 72 waterline vertices) with 41 free-surface rings out to
// 3 wavelengths of T = 8 s (2,952 panels):
//   TdSetup     wetted surface, free-surface mesh, influence assembly, LU, adjoint force maps
//               (counters: assembly_s, lu_s, maps_s as measured inside, N)
//   TdStep      one emp step (one right-hand side, one back-substitution, free-surface update,
//               memory force), hull moving in heave
// Run: bench_rankine_td --benchmark_format=json (see docs/performance.md).
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include "forces/hydro/emp_scheme.hpp"
#include "forces/hydro/hull_shapes.hpp"
#include "forces/hydro/rankine_td_model.hpp"

using namespace yardsim::forces::hydro;

namespace {

RankineTdSettings issueSize() {
  const double g = 9.80665, period = 8.0, lambda = g * period * period / (2.0 * std::numbers::pi);
  RankineTdSettings s;
  s.freeSurface.firstSpacing = 0.9;
  s.freeSurface.maxSpacing = lambda / 10.0;
  s.freeSurface.growth = 1.15;
  s.freeSurface.truncationRadius = 10.0 + 3.0 * lambda;
  s.freeSurface = defaultBeach(s.freeSurface, period, g);
  return s;
}

void benchSetup(benchmark::State& st) {
  const PanelMesh hull = cubeSphere(10.0, 18);
  double assembly = 0.0, lu = 0.0, maps = 0.0;
  int n = 0;
  for (auto _ : st) {
    const RankineTdModel model(hull, yardsim::dynamics::Transform{}, issueSize());
    assembly = model.problem().assemblySeconds();
    lu = model.problem().factorSeconds();
    maps = model.mapSeconds();
    n = model.problem().size();
    benchmark::DoNotOptimize(&model);
  }
  st.counters["assembly_s"] = assembly;
  st.counters["lu_s"] = lu;
  st.counters["maps_s"] = maps;
  st.counters["N"] = n;
}

void benchStep(benchmark::State& st) {
  const RankineTdModel model(cubeSphere(10.0, 18), yardsim::dynamics::Transform{}, issueSize());
  FreeSurfaceState state = quietSurface(model);
  EmpScratch scratch = makeEmpScratch(model);
  const double dt = 8.0 / 40.0;
  const Eigen::VectorXd heave = model.modes().col(2), none;
  Eigen::VectorXd a(heave.size());
  int n = 0;
  for (auto _ : st) {
    a = std::sin(2.0 * std::numbers::pi * n * dt / 8.0) * heave;
    benchmark::DoNotOptimize(empStep(model, dt, a, none, state, scratch).data());
    ++n;
  }
  st.counters["Nb"] = model.problem().bodyCount();
  st.counters["Nf"] = model.problem().surfaceCount();
  st.counters["dt_over_emp_limit"] = dt / empLimit(model, 30).dtMax;
}

}  // namespace

BENCHMARK(benchSetup)->Name("TdSetup")->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(benchStep)->Name("TdStep")->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
