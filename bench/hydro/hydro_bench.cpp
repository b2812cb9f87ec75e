// The Rankine-panel solver on a sphere in unbounded fluid (equiangular cube sphere, 6 n^2 quads):
//   Assembly/N   influence matrices S and D (exact integrals near, one-point rule far)
//   LU/N         K = 2 pi I - D and its partial-pivot LU (once per geometry)
//   BackSub/N    one right-hand side through the LU factors
//   Gmres/N      one right-hand side by restarted GMRES (counter: iterations)
// Run: bench_hydro --benchmark_format=json (see docs/performance.md).
#include <benchmark/benchmark.h>

#include <cmath>

#include "forces/hydro/added_mass.hpp"
#include "forces/hydro/hull_shapes.hpp"

using namespace yardsim::forces::hydro;

namespace {

int divisions(benchmark::State& st) { return static_cast<int>(std::lround(std::sqrt(static_cast<double>(st.range(0)) / 6.0))); }

void benchAssembly(benchmark::State& st) {
  const std::vector<Panel> panels = buildPanels(cubeSphere(1.0, divisions(st)));
  for (auto _ : st) {
    InfluenceMatrices m = assembleInfluence(panels, FreeSurface::None);
    benchmark::DoNotOptimize(m.source.data());
  }
}

void benchLu(benchmark::State& st) {
  const std::vector<Panel> panels = buildPanels(cubeSphere(1.0, divisions(st)));
  const InfluenceMatrices assembled = assembleInfluence(panels, FreeSurface::None);
  for (auto _ : st) {
    st.PauseTiming();
    InfluenceMatrices copy = assembled;
    st.ResumeTiming();
    const PotentialSolver solver(panels, SolverOptions{}, std::move(copy));
    benchmark::DoNotOptimize(&solver);
  }
}

// (linear solver) => one right-hand side (surge) solved through K
template <LinearSolver kSolver>
void benchSolve(benchmark::State& st) {
  const std::vector<Panel> panels = buildPanels(cubeSphere(1.0, divisions(st)));
  SolverOptions o;
  o.linearSolver = kSolver;
  const PotentialSolver solver(panels, o);
  const Eigen::MatrixXd rhs = -(assembleInfluence(panels, FreeSurface::None).source * modeNormals(panels, Vector3::Zero()).col(0));
  for (auto _ : st) {
    const Eigen::MatrixXd phi = solver.solveSystem(rhs);
    benchmark::DoNotOptimize(phi.data());
  }
  st.counters["iterations"] = solver.lastIterations();
}

}  // namespace

BENCHMARK(benchAssembly)->Name("Assembly")->Arg(384)->Arg(1536)->Arg(4056)->Unit(benchmark::kMillisecond);
BENCHMARK(benchLu)->Name("LU")->Arg(384)->Arg(1536)->Arg(4056)->Unit(benchmark::kMillisecond);
BENCHMARK(benchSolve<LinearSolver::DenseLU>)->Name("BackSub")->Arg(384)->Arg(1536)->Arg(4056)->Unit(benchmark::kMillisecond);
BENCHMARK(benchSolve<LinearSolver::Gmres>)->Name("Gmres")->Arg(384)->Arg(1536)->Arg(4056)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
