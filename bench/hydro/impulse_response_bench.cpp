// The impulse-response path (docs/performance.md, "Impulse-response path"):
//   Convolution/h_ms   one mechanics step of RK4 on the radiation memory of one body, 6 modes
//                      (full 6x6 K), 60 s of memory at 0.05 s: one commit and four stages; h in ms
//   Excitation/N       the wave excitation of a sea of N components at one stage, two headings
//   IrregularSea/N     discretising a JONSWAP sea into N components
// Target (issue 16): Convolution at most 20 us per step.
// Run: bench_hydro_ir --benchmark_format=json (see docs/performance.md).
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>

#include "dynamics/kinematics.hpp"
#include "dynamics/model_builder.hpp"
#include "forces/hydro/impulse_response_force.hpp"
#include "forces/hydro/irregular_sea.hpp"
#include "forces/hydro/radiation_memory.hpp"

using namespace yardsim;
using namespace yardsim::forces;
using namespace yardsim::forces::hydro;

namespace {

// (headings) => 60 s of a full, decaying 6x6 K at 0.05 s and excitation pulses
std::shared_ptr<ImpulseResponse> response(std::vector<double> headings) {
  auto ir = std::make_shared<ImpulseResponse>();
  ir->dt = 0.05;
  for (int k = 0; k < 1200; ++k) {
    ImpulseResponse::Matrix6 K;
    for (int i = 0; i < 36; ++i)
      K(i / 6, i % 6) = (1.0 + i) * std::exp(-0.3 * k * 0.05) * std::cos(0.8 * k * 0.05 + i);
    ir->radiation.push_back(K);
  }
  ir->headings = std::move(headings);
  ir->excitationStart = -3.0;
  ir->excitation.assign(ir->headings.size(), std::vector<ImpulseResponse::Vector6>(
                                                 120, ImpulseResponse::Vector6::Ones()));
  return ir;
}

void benchConvolution(benchmark::State& st) {
  const auto ir = response({});
  const RetardationKernel kernel(*ir);
  RadiationMemory memory(kernel);
  const double h = static_cast<double>(st.range(0)) * 1e-3;
  double t = 0.0;
  ImpulseResponse::Vector6 v, sink = ImpulseResponse::Vector6::Zero();
  for (auto _ : st) {
    for (int i = 0; i < 6; ++i) v[i] = std::sin(0.7 * t + i);
    memory.commit(t, v);
    sink += memory.convolution(t, v);
    sink += memory.convolution(t + 0.5 * h, v);
    sink += memory.convolution(t + 0.5 * h, v);
    sink += memory.convolution(t + h, v);
    t += h;
  }
  benchmark::DoNotOptimize(sink.data());
}

void benchExcitation(benchmark::State& st) {
  dynamics::ModelBuilder b;
  b.addBody("barge", "world", dynamics::Joint::free(), dynamics::Transform::identity(),
            dynamics::boxInertia(1e6, dynamics::Vector3(60, 20, 5)));
  const dynamics::Model model = b.build();
  IrregularSea spec;
  spec.hs = 2.5, spec.tp = 8.0, spec.spreadingS = 10,
  spec.components = static_cast<int>(st.range(0));
  const auto sea = std::make_shared<const AiryWaves>(WaterProperties{}, irregularWaves(spec));
  const ImpulseResponseForce p("hd", model, 1, response({0.0, M_PI / 2}), sea);
  dynamics::Data data(model);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(model.nq), v = Eigen::VectorXd::Zero(model.nv);
  q[3] = 1.0;
  dynamics::forwardKinematics(model, data, q, v);
  double t = 0.0;
  ImpulseResponse::Vector6 sink = ImpulseResponse::Vector6::Zero();
  for (auto _ : st) {
    sink += p.excitation(Stage{t, model, data, q, v});
    t += 0.01;
  }
  benchmark::DoNotOptimize(sink.data());
}

void benchIrregularSea(benchmark::State& st) {
  IrregularSea spec;
  spec.hs = 2.5, spec.tp = 8.0, spec.spreadingS = 10,
  spec.components = static_cast<int>(st.range(0));
  for (auto _ : st) {
    auto w = irregularWaves(spec);
    benchmark::DoNotOptimize(w.data());
  }
}

}  // namespace

BENCHMARK(benchConvolution)
    ->Name("Convolution")
    ->Arg(10)
    ->Arg(50)
    ->Arg(100)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(benchExcitation)->Name("Excitation")->Arg(50)->Arg(200)->Unit(benchmark::kMicrosecond);
BENCHMARK(benchIrregularSea)->Name("IrregularSea")->Arg(200)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
