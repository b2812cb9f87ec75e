// The quasi-static catenary's cost per line per stage (issue 17: <= 1 us on a warm start): the
// fairlead moves 1 mm between calls, as between the stages of a 0.05 s step at 2 cm/s.
#include <benchmark/benchmark.h>

#include "dynamics/kinematics.hpp"
#include "dynamics/model_builder.hpp"
#include "forces/lines/catenary_line.hpp"

using namespace yardsim;
using namespace yardsim::forces;

namespace {

// (state.range(0): 0 suspended, 1 touching down, 2 touching down with friction) => parameters
CatenaryParameters line(int kind) {
  return {500.0, 7.5e8, 1020.0, kind > 0, kind == 2 ? 1.0 : 0.0};
}

// (kind) => warm-started solves, the fairlead walking back and forth by 1 mm per call
void BM_CatenaryWarm(benchmark::State& state) {
  const CatenaryParameters p = line(static_cast<int>(state.range(0)));
  CatenarySolution s = solveCatenary(p, 400.0, 200.0);
  int k = 0, iterations = 0;
  for (auto _ : state) {
    const double dx = 1e-3 * (k % 200 < 100 ? k % 100 : 100 - k % 100);
    s = solveCatenary(p, 400.0 + dx, 200.0 - 0.5 * dx, s.hf, s.vf);
    iterations += s.iterations;
    benchmark::DoNotOptimize(s.hf);
    ++k;
  }
  state.counters["newton_iterations"] =
      benchmark::Counter(static_cast<double>(iterations), benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_CatenaryWarm)->Arg(0)->Arg(1)->Arg(2);

// (kind) => cold-start solves
void BM_CatenaryCold(benchmark::State& state) {
  const CatenaryParameters p = line(static_cast<int>(state.range(0)));
  int k = 0;
  for (auto _ : state) {
    const CatenarySolution s = solveCatenary(p, 400.0 + 1e-3 * (k % 100), 200.0);
    benchmark::DoNotOptimize(s.hf);
    ++k;
  }
}
BENCHMARK(BM_CatenaryCold)->Arg(0)->Arg(1)->Arg(2);

// one CatenaryLine::evaluate() on a free body moving 1 mm per call, with its forward kinematics
void BM_CatenaryLineEvaluate(benchmark::State& state) {
  dynamics::ModelBuilder b;
  b.setGravity(dynamics::Vector3::Zero());
  b.addBody("barge", "world", dynamics::Joint::free(), dynamics::Transform::identity(),
            dynamics::boxInertia(2e6, dynamics::Vector3(40, 12, 5)));
  const dynamics::Model m = b.build();
  CatenaryLine l("l", m, {0, dynamics::Vector3(-420, 0, -150)}, {1, dynamics::Vector3(-20, 0, 0)},
                 line(1));
  dynamics::Data d(m);
  Eigen::VectorXd q(7), v = Eigen::VectorXd::Zero(6);
  q << 0, 0, 0, 1, 0, 0, 0;
  dynamics::ExternalForces f(m);
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(6);
  int k = 0;
  for (auto _ : state) {
    q[0] = 1e-3 * (k % 100);
    dynamics::forwardKinematics(m, d, q, v);
    l.evaluate({0.0, m, d, q, v}, f, tau);
    ++k;
  }
}
BENCHMARK(BM_CatenaryLineEvaluate);

}  // namespace

BENCHMARK_MAIN();
