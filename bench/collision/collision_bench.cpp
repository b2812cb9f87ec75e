// The collision kernel's speed (issue 15 targets in docs/performance.md, "Collision kernel"):
//  BM_BroadPhase/parts/tight: one step of the yard: 10 % of the parts moved, the tree updated,
//    the filtered candidate pairs collected (tight = 0: FCL's default boxes, for comparison)
//  BM_FullCheck/parts/meshes/k/reuse: the same step plus the contacts of every candidate pair, up
//    to k points per pair (meshes = 0: the mesh blocks replaced by boxes; reuse = 0: every pair
//    through the narrow phase, 1: pairs whose objects did not move keep last step's contacts)
//  BM_RopeBoxDistance: one rope segment moved and its distance to a block with witness points
//    (segmentBoxDistance, not FCL's GJK)
//  BM_RopeClearanceWatch/parts: a hoist rope's four segments moved and watched against every
//    block of the yard, margin 1 m (only nearby pairs are queried)
//  BM_Hulls/all: two ~19k-triangle hulls overlapping by 5 cm: first contact (all = 0) or all
//    contact points (all = 1)
// Run: build/bench/collision/bench_collision (one thread). Doubles go to DoNotOptimize as const
// references: the non-const form miscompiles with GCC (google/benchmark#903, GCC bug 92597) and
// showed impossible values in the counters.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <utility>

#include "dynamics/rotation.hpp"
#include "forces/geometry/primitive_meshes.hpp"
#include "yard.hpp"

using namespace yardsim;
using collision::CollisionWorld;
using collision::Shape;
using dynamics::Transform;
using dynamics::Vector3;

namespace {

void BM_BroadPhase(benchmark::State& st) {
  bench::Yard y = bench::makeYard(static_cast<int>(st.range(0)), st.range(1) != 0);
  double t = 0.0;
  std::size_t pairs = 0;
  for (auto _ : st) {
    bench::moveYard(y, t);
    pairs = y.world.candidatePairs().size();
    benchmark::DoNotOptimize(pairs);
    t += 0.05;
  }
  st.counters["parts"] = y.parts;
  st.counters["moving"] = static_cast<double>(y.movers.size());
  st.counters["candidates"] = static_cast<double>(pairs);
  st.counters["box_pairs"] = y.world.stats().broadPhasePairs;
}
BENCHMARK(BM_BroadPhase)
    ->Args({10000, 1})
    ->Args({10000, 0})
    ->Args({30000, 1})
    ->Unit(benchmark::kMillisecond);

void BM_FullCheck(benchmark::State& st) {
  bench::Yard y =
      bench::makeYard(static_cast<int>(st.range(0)), true, st.range(1) != 0, st.range(3) != 0);
  st.SetLabel(std::string(st.range(1) != 0 ? "meshes" : "boxes only") +
              (st.range(3) != 0 ? ", reuse" : ", no reuse"));
  double t = 0.0;
  for (auto _ : st) {
    bench::moveYard(y, t);
    benchmark::DoNotOptimize(y.world.contacts(static_cast<int>(st.range(2))).size());
    t += 0.05;
  }
  st.counters["parts"] = y.parts;
  st.counters["candidates"] = y.world.stats().candidatePairs;
  st.counters["narrow_calls"] = y.world.stats().narrowPhaseCalls;
  st.counters["reused"] = y.world.stats().reusedPairs;
  st.counters["contacts"] = y.world.stats().contacts;
}
BENCHMARK(BM_FullCheck)
    ->Args({10000, 1, 4, 1})
    ->Args({10000, 1, 4, 0})
    ->Args({10000, 0, 4, 0})
    ->Args({10000, 1, 1, 0})
    ->Args({30000, 1, 4, 1})
    ->Args({30000, 1, 4, 0})
    ->Args({30000, 0, 4, 0})
    ->Unit(benchmark::kMillisecond);

void BM_RopeBoxDistance(benchmark::State& st) {
  CollisionWorld w;
  const auto box = w.add(Shape::box(Vector3(10, 8, 4)),
                         Transform::rotation(dynamics::axisRotation(Vector3::UnitZ(), 0.35)));
  const auto seg = w.addSegment(Vector3(-6, 0, 3), Vector3(6, 1, 6), 0.05);
  double t = 0.0, d = 0.0, dmin = 1e300;
  for (auto _ : st) {
    const Vector3 sway(0.5 * std::sin(t), 0.5 * std::cos(1.3 * t), 0.0);
    w.setSegment(seg, Vector3(-6, 0, 3) + sway, Vector3(6, 1, 6) + 0.3 * sway);
    d = w.distance(seg, box).distance;
    dmin = std::min(dmin, d);
    benchmark::DoNotOptimize(std::as_const(d));
    t += 0.01;
  }
  st.counters["min_distance"] = dmin;  // the rope stays >= 3 - 2 - 0.025 m above the block
}
BENCHMARK(BM_RopeBoxDistance)->Unit(benchmark::kMicrosecond);

void BM_RopeClearanceWatch(benchmark::State& st) {
  bench::Yard y = bench::makeYard(static_cast<int>(st.range(0)));
  // the first site's rope, swaying, against every block of the yard; the rest of the yard still
  const std::vector<collision::ObjectId> rope(y.ropeSegments.begin(), y.ropeSegments.begin() + 4);
  std::vector<bench::Yard::Mover> segments;
  for (const auto& m : y.movers)
    if (m.segment && std::find(rope.begin(), rope.end(), m.id) != rope.end()) segments.push_back(m);
  const int watch = y.world.addWatch(rope, y.blocks, 1.0);
  double t = 0.0, closest = 0.0;
  int queried = 0;
  for (auto _ : st) {
    const double s = std::sin(1.3 * t);
    const Vector3 side(0.3 * s, 0.15 * s, 0.0);
    for (const auto& m : segments) y.world.setSegment(m.id, m.p0 + m.f0 * side, m.p1 + m.f1 * side);
    const auto& c = y.world.clearance(watch);
    queried = c.pairsQueried;
    closest = c.closest.distance;
    benchmark::DoNotOptimize(std::as_const(closest));
    t += 0.05;
  }
  st.counters["pairs_queried"] = queried;
  st.counters["closest"] = closest;
  st.counters["blocks"] = static_cast<double>(y.blocks.size());
}
BENCHMARK(BM_RopeClearanceWatch)->Arg(10000)->Unit(benchmark::kMicrosecond);

void BM_Hulls(benchmark::State& st) {
  auto hull = std::make_shared<const forces::TriangleMesh>(forces::sphereMesh(10.0, 70, 140));
  CollisionWorld w(collision::WorldOptions{true, false, false});  // the narrow phase every time
  const auto a = w.add(Shape::triangleMesh(hull), Transform::identity());
  // the second hull turned (so that no triangles line up), its inscribed polyhedron 5 cm into
  // the first's along x (the polyhedra reach 10 m at their poles on x after the turns)
  const dynamics::Matrix3 R = dynamics::axisRotation(Vector3(1, 2, 3).normalized(), 0.4);
  const double reach = hull->vertices.front().norm();
  w.add(Shape::triangleMesh(hull), Transform{R, Vector3(2.0 * reach - 0.05, 0.0, 0.0)});
  (void)a;
  std::size_t n = 0;
  bool hit = false;
  for (auto _ : st) {
    if (st.range(0) == 0) {
      hit = w.anyInterference();
      benchmark::DoNotOptimize(hit);
    } else {
      n = w.contacts(1'000'000).size();
      benchmark::DoNotOptimize(n);
    }
  }
  st.counters["triangles"] = static_cast<double>(hull->triangles.size());
  st.counters["contacts"] = static_cast<double>(st.range(0) == 0 ? (hit ? 1 : 0) : n);
}
BENCHMARK(BM_Hulls)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
