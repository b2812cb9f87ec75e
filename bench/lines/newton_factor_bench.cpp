// The lumped lines' Newton matrix factorised: 8 lines of n - 1 three-dof nodes each, banded along
// each line, the nodes next to the fairlead coupled to 2 rigid dofs (the shape of
// bench_lumped_lines' scene), diagonally dominant values. BorderedBandLu (the path
// SparseNewtonMatrix takes for it) against Eigen's SparseLU with COLAMD (the path before it and the
// fallback), one numeric factorisation per iteration; the counter ns_per_row shows the slope in n.
// See docs/performance.md, "The factorisation of the lines' Newton matrix".
#include <benchmark/benchmark.h>

#include <Eigen/SparseLU>
#include <random>
#include <vector>

#include "dynamics/integrators/bordered_band_lu.hpp"

namespace {

// (segments per line) => A: rigid dofs 0 and 1, then line by line 3 (segments - 1) node dofs
Eigen::SparseMatrix<double> linesMatrix(int segments) {
  const int nodes = segments - 1, lines = 8, n = 2 + 3 * nodes * lines;
  std::mt19937 rng(3u);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Eigen::Triplet<double>> t;
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 2; ++c) t.emplace_back(r, c, r == c ? 50.0 : u(rng));
  for (int l = 0; l < lines; ++l)
    for (int k = 0; k < nodes; ++k) {
      const int at = 2 + 3 * (nodes * l + k);
      for (int o = std::max(0, k - 1); o <= std::min(nodes - 1, k + 1); ++o)
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b) {
            const int row = at + a, col = 2 + 3 * (nodes * l + o) + b;
            t.emplace_back(row, col, row == col ? 20.0 : u(rng));
          }
      if (k == nodes - 1)
        for (int a = 0; a < 3; ++a)
          for (int r = 0; r < 2; ++r) {
            t.emplace_back(at + a, r, u(rng));
            t.emplace_back(r, at + a, u(rng));
          }
    }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  return A;
}

// (state, A) => the counter ns_per_row: time per factorisation / rows
void perRow(benchmark::State& state, const Eigen::SparseMatrix<double>& A) {
  state.counters["ns_per_row"] = benchmark::Counter(
      static_cast<double>(A.rows()),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// (benchmark) => 10 to 160 segments per line, timed in microseconds
void sizes(benchmark::internal::Benchmark* b) {
  for (int s : {10, 20, 40, 80, 160}) b->Arg(s);
  b->Unit(benchmark::kMicrosecond);
}

void BM_BandedFactorise(benchmark::State& state) {
  const Eigen::SparseMatrix<double> A = linesMatrix(static_cast<int>(state.range(0)));
  yardsim::dynamics::BorderedBandLu lu;
  if (!lu.analyse(A)) state.SkipWithError("not a bordered band matrix");
  for (auto _ : state) benchmark::DoNotOptimize(lu.factorise(A));
  perRow(state, A);
  state.counters["border"] = lu.border();
  state.counters["band"] = lu.bandwidth();
}
BENCHMARK(BM_BandedFactorise)->Apply(sizes);

void BM_SparseLuFactorise(benchmark::State& state) {
  const Eigen::SparseMatrix<double> A = linesMatrix(static_cast<int>(state.range(0)));
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;
  lu.analyzePattern(A);
  for (auto _ : state) {
    lu.factorize(A);
    benchmark::DoNotOptimize(lu.info());
  }
  perRow(state, A);
}
BENCHMARK(BM_SparseLuFactorise)->Apply(sizes);

}  // namespace

BENCHMARK_MAIN();
