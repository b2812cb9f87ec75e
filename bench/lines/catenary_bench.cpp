// The quasi-static catenary's cost per line per stage (issue 17: <= 1 us on a warm start): the
// fairlead moves 1 mm between calls, as between the stages of a 0.05 s step at 2 cm/s; and the
// lumped-mass line's node forces per evaluation.
#include <benchmark/benchmark.h>

#include "dynamics/kinematics.hpp"
#include "dynamics/model_builder.hpp"
#include "forces/lines/catenary_line.hpp"
#include "forces/lines/lumped_line.hpp"

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
    // the whole struct: with DoNotOptimize(s.hf) (benchmark 1.7.1's "+m,r" asm on a double,
    // g++ 12) every warm start here ran like a cold one (docs/performance.md)
    benchmark::DoNotOptimize(s);
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
    benchmark::DoNotOptimize(s);
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

// (segments) => one LumpedLine::nodeForces of a 500 m chain in a current and a regular wave
void BM_LumpedLineForces(benchmark::State& state) {
  LumpedLineProperties p;
  p.length = 500.0;
  p.segments = static_cast<int>(state.range(0));
  p.diameter = 0.12;
  p.massPerLength = 120.0;
  p.ea = 7.5e8;
  p.damping = -0.5;
  p.cdn = 1.2;
  p.cdt = 0.4;
  p.can = 1.0;
  p.cat = 0.1;
  p.seabed = true;
  p.seabedZ = -200.0;
  p.bedStiffness = 1e7;
  p.bedFriction = 0.5;
  WaterProperties water;
  water.depth = 200.0;
  const AiryWaves waves(water, {{3.0, 10.0, 0.0, 0.0}});
  CurrentProperties cp;
  cp.speed = 0.8;
  const CurrentField current(cp);
  const LumpedLine line(p, "chain", &waves, &current);
  const int n = line.nodes();
  Eigen::Matrix3Xd r(3, n), v = Eigen::Matrix3Xd::Constant(3, n, 0.01), f(3, n);
  for (int i = 0; i < n; ++i) {  // the first 40 % on the bed, then straight up to the fairlead
    const double s = static_cast<double>(i) / p.segments;
    r.col(i) = s < 0.4
                   ? dynamics::Vector3(500.0 * s, 0.0, -200.0)
                   : dynamics::Vector3(200.0 + 200.0 * (s - 0.4), 0.0, -200.0 + 330.0 * (s - 0.4));
  }
  Eigen::VectorXd tension(p.segments);
  double t = 0.0;
  for (auto _ : state) {
    line.nodeForces(r, v, t, f, tension);
    benchmark::DoNotOptimize(f.data());
    t += 1e-3;
  }
  state.counters["per_node_ns"] =
      benchmark::Counter(static_cast<double>(n), benchmark::Counter::kIsIterationInvariantRate |
                                                     benchmark::Counter::kInvert);
}
BENCHMARK(BM_LumpedLineForces)->Arg(20)->Arg(40)->Arg(80);

}  // namespace

BENCHMARK_MAIN();
