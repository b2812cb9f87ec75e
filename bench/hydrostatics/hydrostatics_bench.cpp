// Hydrostatics per evaluation: a UV sphere hull (the inscribed polyhedron, radius 10 m) heeled by
// 20 deg and half immersed, meshed with ~1 k (960), ~10 k (9 800) and ~100 k (101 760) triangles;
// Hydrostatics::evaluate in calm water, in one regular Airy wave and in a sea of 20 components,
// and integrateSubmerged alone.
// Run: bench_hydrostatics (see docs/performance.md for the recorded figures).
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>

#include "dynamics/kinematics.hpp"
#include "dynamics/model_builder.hpp"
#include "dynamics/rotation.hpp"
#include "forces/geometry/primitive_meshes.hpp"
#include "forces/geometry/submerged_mesh.hpp"
#include "forces/hydrostatics.hpp"

using namespace yardsim;
using namespace yardsim::forces;
using dynamics::Vector3;

namespace {

// (size index 0, 1, 2) => bands, segments of a sphere with ~1 k, 10 k, 100 k triangles
TriangleMesh hull(int64_t n) {
  const int bands[3] = {16, 50, 160};
  return sphereMesh(10.0, bands[n], 2 * bands[n]);
}

// (components: 0 calm, 1 a regular wave, more: an irregular sea of small components) => the sea
std::shared_ptr<const AiryWaves> sea(int components) {
  const WaterProperties water{1025.0, 9.81, 0.0, 50.0, 0.0, 0.0};
  if (components == 1)
    return std::make_shared<const AiryWaves>(water,
                                             std::vector<WaveComponent>{{3.0, 9.0, 0.5, 0.0}});
  std::vector<WaveComponent> waves;
  for (int i = 0; i < components; ++i)
    waves.push_back({0.3, 6.0 + 0.4 * i, 0.5 + 0.05 * i, 0.9 * i});
  return std::make_shared<const AiryWaves>(water, waves);
}

void evaluate(benchmark::State& st, int waves) {
  dynamics::ModelBuilder b;
  b.setGravity(Vector3::Zero());
  b.addBody("buoy", "world", dynamics::Joint::free(), dynamics::Transform::identity(),
            dynamics::boxInertia(2e6, Vector3(20, 20, 20)));
  const dynamics::Model model = b.build();
  const TriangleMesh mesh = hull(st.range(0));
  Hydrostatics hydro("hull", model, 1, mesh, sea(waves));
  dynamics::Data data(model);
  Eigen::VectorXd q(7), v = Eigen::VectorXd::Zero(6), tau = Eigen::VectorXd::Zero(6);
  double quat[4];
  dynamics::matrixToQuaternion(dynamics::axisRotation(Vector3::UnitX(), 20.0 * M_PI / 180), quat);
  q << 0.0, 0.0, 0.3, quat[0], quat[1], quat[2], quat[3];
  dynamics::forwardKinematics(model, data, q, v);
  dynamics::ExternalForces f(model);
  double t = 0.0;
  const auto scratch = hydro.makeScratch();  // the caller's, made once (as mechanics::Data does)
  for (auto _ : st) {
    f.clear();
    hydro.evaluate(forces::Stage{t, model, data, q, v, scratch.get()}, f, tau);
    benchmark::DoNotOptimize(f.worldFrame(1));
    t += 1e-3;
  }
  st.counters["triangles"] = static_cast<double>(mesh.triangles.size());
  st.counters["wet_volume"] = hydro.report(forces::Stage{t, model, data, q, v, scratch.get()}).submerged.volume;
}

void Calm(benchmark::State& st) {
  evaluate(st, 0);
}
void Waves(benchmark::State& st) {
  evaluate(st, 1);
}
void Irregular(benchmark::State& st) {
  evaluate(st, 20);
}

void ClipOnly(benchmark::State& st) {
  const TriangleMesh mesh = hull(st.range(0));
  SubmergedWorkspace ws(mesh);
  const auto water = sea(0);
  const dynamics::Transform X{dynamics::axisRotation(Vector3::UnitX(), 20.0 * M_PI / 180), Vector3(0, 0, 0.3)};
  for (auto _ : st) benchmark::DoNotOptimize(integrateSubmerged(mesh, X, *water, 0.0, ws).volume);
  st.counters["triangles"] = static_cast<double>(mesh.triangles.size());
}

}  // namespace

BENCHMARK(Calm)->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK(Waves)->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK(Irregular)->DenseRange(0, 1)->Unit(benchmark::kMicrosecond);
BENCHMARK(ClipOnly)->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
