// yardsim's multibody kernel: ABA, RNEA, CRBA + Cholesky and one RK4 step, on a planar chain of
// N links (ABA/N ...) and on a binary tree (ABATree/N ...), and the double-pendulum energy drift.
// Run: bench_multibody --benchmark_format=json (see docs/performance.md).
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "bench_models.hpp"
#include "dynamics/aba.hpp"
#include "dynamics/crba.hpp"
#include "dynamics/tree_cholesky.hpp"
#include "dynamics/energy.hpp"
#include "dynamics/integrators/rk4.hpp"
#include "dynamics/multibody_system.hpp"
#include "dynamics/rnea.hpp"

using namespace yardsim;
using namespace yardsim::dynamics;

namespace {

struct State {
  Eigen::VectorXd q, v, tau;
  explicit State(int nv) {
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    q.resize(nv);
    v.resize(nv);
    tau.resize(nv);
    for (int i = 0; i < nv; ++i) {
      q[i] = u(rng);
      v[i] = u(rng);
      tau[i] = u(rng);
    }
  }
};

template <Model (*Make)(int)>
void benchAba(benchmark::State& st) {
  const Model m = Make(static_cast<int>(st.range(0)));
  Data d(m);
  State s(m.nv);
  for (auto _ : st) benchmark::DoNotOptimize(aba(m, d, s.q, s.v, s.tau).data());
  st.counters["ns_per_link"] = benchmark::Counter(static_cast<double>(m.nv), benchmark::Counter::kIsIterationInvariantRate |
                                                                                  benchmark::Counter::kInvert);
}

template <Model (*Make)(int)>
void benchRnea(benchmark::State& st) {
  const Model m = Make(static_cast<int>(st.range(0)));
  Data d(m);
  State s(m.nv);
  for (auto _ : st) benchmark::DoNotOptimize(rnea(m, d, s.q, s.v, s.tau).data());
  st.counters["ns_per_link"] = benchmark::Counter(static_cast<double>(m.nv), benchmark::Counter::kIsIterationInvariantRate |
                                                                                  benchmark::Counter::kInvert);
}

template <Model (*Make)(int)>
void benchCrba(benchmark::State& st) {
  const Model m = Make(static_cast<int>(st.range(0)));
  Data d(m);
  State s(m.nv);
  for (auto _ : st) {
    crba(m, d, s.q);
    choleskyFactor(m, d);
    benchmark::DoNotOptimize(d.L.data());
  }
}

template <Model (*Make)(int)>
void benchCrbaOnly(benchmark::State& st) {
  const Model m = Make(static_cast<int>(st.range(0)));
  Data d(m);
  State s(m.nv);
  for (auto _ : st) benchmark::DoNotOptimize(crba(m, d, s.q).data());
}

// (N) => time per RK4 step of the chain released horizontally from rest; like the ODE cases, the
// state is reset (untimed) every 200 steps so that every run integrates the same 0.2 s of motion.
void benchRk4Step(benchmark::State& st) {
  const Model m = bench::chainModel(static_cast<int>(st.range(0)));
  MultibodySystem sys(m);
  Rk4 rk(m);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(m.nq), v = Eigen::VectorXd::Zero(m.nv);
  double t = 0.0;
  long k = 0;
  for (auto _ : st) {
    rk.step(sys, t, q, v, 1e-3);
    benchmark::DoNotOptimize(q.data());
    if (++k % bench::kResetSteps == 0) {
      st.PauseTiming();
      q.setZero();
      v.setZero();
      t = 0.0;
      st.ResumeTiming();
    }
  }
}

void benchDrift(benchmark::State& st) {
  double drift = 0.0;
  for (auto _ : st) drift = bench::yardsimDoublePendulumDrift(1e-3, 10.0);
  st.counters["relative_energy_drift"] = drift;
}

}  // namespace

double bench::yardsimDoublePendulumDrift(double dt, double duration) {
  const Model m = chainModel(2);
  Data d(m);
  MultibodySystem sys(m);
  Rk4 rk(m);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(2), v = Eigen::VectorXd::Zero(2), hanging(2);
  hanging << M_PI / 2, 0.0;
  const double Emin = potentialEnergy(m, d, hanging);
  const double E0 = potentialEnergy(m, d, q) - Emin;
  double t = 0.0, drift = 0.0;
  const long steps = std::lround(duration / dt);
  for (long k = 0; k < steps; ++k) {
    rk.step(sys, t, q, v, dt);
    const double E = kineticEnergy(m, d, q, v) + potentialEnergy(m, d, q) - Emin;
    drift = std::max(drift, std::abs(E - E0) / E0);
  }
  return drift;
}

BENCHMARK(benchAba<bench::chainModel>)->Name("ABA")->RangeMultiplier(2)->Range(1, 256);
BENCHMARK(benchRnea<bench::chainModel>)->Name("RNEA")->RangeMultiplier(2)->Range(1, 256);
BENCHMARK(benchCrba<bench::chainModel>)->Name("CRBA")->RangeMultiplier(2)->Range(1, 256);
BENCHMARK(benchCrbaOnly<bench::chainModel>)->Name("CRBANoCholesky")->RangeMultiplier(2)->Range(1, 256);
BENCHMARK(benchRk4Step)->Name("RK4Step")->RangeMultiplier(2)->Range(1, 256);
BENCHMARK(benchAba<bench::binaryTreeModel>)->Name("ABATree")->RangeMultiplier(2)->Range(1, 256);
BENCHMARK(benchRnea<bench::binaryTreeModel>)->Name("RNEATree")->RangeMultiplier(2)->Range(1, 256);
BENCHMARK(benchCrba<bench::binaryTreeModel>)->Name("CRBATree")->RangeMultiplier(2)->Range(1, 256);
BENCHMARK(benchDrift)->Name("EnergyDrift/YardsimRK4")->Iterations(1)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
