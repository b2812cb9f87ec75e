#include "yard.hpp"

#include <cmath>
#include <memory>
#include <random>

#include "dynamics/rotation.hpp"
#include "forces/geometry/primitive_meshes.hpp"

namespace yardsim::bench {

using collision::ObjectOptions;
using collision::Shape;
using dynamics::Transform;
using dynamics::Vector3;

namespace {

constexpr double kSide = 1000.0;  // m
constexpr int kSiteParts = 7, kStackParts = 3;
constexpr int kRopeSegments = 4;

// (top, hook, sway m) => the rope's path: straight from top to hook, bowed sideways
std::vector<Vector3> ropePath(const Vector3& top, const Vector3& hook, double sway) {
  std::vector<Vector3> p;
  for (int i = 0; i <= kRopeSegments; ++i) {
    const double s = static_cast<double>(i) / kRopeSegments;
    p.push_back(top + s * (hook - top) + Vector3(sway * s, 0.5 * sway * s, 0.0));
  }
  return p;
}

}  // namespace

// (parts, options) => sites and stacks until parts are placed; a tenth of them moving
Yard makeYard(int parts, bool tightAabb, bool meshBlocks, bool reuse) {
  Yard y{
      collision::CollisionWorld(collision::WorldOptions{tightAabb, false, reuse}), {}, {}, {}, 0};
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto blockMesh = std::make_shared<const forces::TriangleMesh>(
      forces::boxMesh(Vector3(10.0, 8.0, 4.0), 4, 4, 4));
  const int activeSites = parts / 10 / 5;  // 5 moving parts per active site: 10 % of the parts
  int owner = 0, site = 0;
  while (y.parts + kSiteParts <= parts) {
    // a site, then a stack, while there is room
    const Vector3 c(kSide * u(rng), kSide * u(rng), 0.0);
    const Transform yaw{dynamics::axisRotation(Vector3::UnitZ(), 2.0 * M_PI * u(rng)), c};
    const bool mesh = meshBlocks && site % 3 == 2;
    const Vector3 size =
        mesh ? Vector3(10, 8, 4) : Vector3(6 + 8 * u(rng), 4 + 6 * u(rng), 2 + 4 * u(rng));
    for (double sx : {-1.0, 1.0}) {
      y.world.add(Shape::box(Vector3(1.0, size.y() + 1.0, 1.0)),
                  yaw * Transform::translation(Vector3(sx * size.x() / 3, 0, 0.5)),
                  ObjectOptions{"support", {owner++, 1u, collision::kAllGroups}});
    }
    const Transform X_block =
        yaw * Transform::translation(Vector3(0, 0, 1.0 + 0.5 * size.z() - 1e-3));
    const int blockOwner = owner++;
    const collision::ObjectId block =
        y.world.add(mesh ? Shape::triangleMesh(blockMesh) : Shape::box(size), X_block,
                    ObjectOptions{"block", {blockOwner, 1u, collision::kAllGroups}});
    y.blocks.push_back(block);
    const Vector3 top = c + Vector3(0, 0, 40.0), hook = c + Vector3(0, 0, 1.0 + size.z() + 0.5);
    const int ropeOwner = owner++;
    const auto rope =
        y.world.addRope(ropePath(top, hook, 0.0), 0.05,
                        ObjectOptions{"hoist", {ropeOwner, 2u, collision::kAllGroups}});
    y.ropeSegments.insert(y.ropeSegments.end(), rope.begin(), rope.end());
    if (site < activeSites) {
      const double phase = 2.0 * M_PI * u(rng);
      y.movers.push_back({block, false, X_block, Vector3::Zero(), Vector3::Zero(), 0, 0, phase});
      const auto path = ropePath(top, hook, 0.0);
      for (std::size_t i = 0; i < rope.size(); ++i) {
        const double f = 1.0 / kRopeSegments;
        y.movers.push_back({rope[i], true, Transform::identity(), path[i], path[i + 1],
                            f * static_cast<double>(i), f * static_cast<double>(i + 1), phase});
      }
    }
    y.parts += kSiteParts;
    ++site;
    if (y.parts + kStackParts > parts) break;
    const Vector3 s(kSide * u(rng), kSide * u(rng), 0.0);
    const double a = 2.0 * M_PI * u(rng);
    for (int level = 0; level < 3; ++level) {
      const double jitter = (u(rng) - 0.5) * 2.0 * M_PI / 180.0;
      y.world.add(Shape::box(Vector3(12.2, 2.44, 2.59)),
                  Transform{dynamics::axisRotation(Vector3::UnitZ(), a + jitter),
                            s + Vector3(0, 0, 1.295 + level * (2.59 - 1e-3))},
                  ObjectOptions{"container", {owner++, 1u, collision::kAllGroups}});
    }
    y.parts += kStackParts;
  }
  y.world.update();
  return y;
}

// (yard, t) => movers at their poses at t: blocks rock 0.3 deg and 2 cm, ropes sway 0.3 m
void moveYard(Yard& y, double t) {
  for (const Yard::Mover& m : y.movers) {
    const double s = std::sin(1.3 * t + m.phase);
    if (m.segment) {
      const Vector3 side(0.3 * s, 0.15 * s, 0.0);
      y.world.setSegment(m.id, m.p0 + m.f0 * side, m.p1 + m.f1 * side);
    } else {
      const Transform rock{dynamics::axisRotation(Vector3::UnitX(), 0.3 * M_PI / 180.0 * s),
                           Vector3(0, 0, 0.02 * s)};
      y.world.setPose(m.id, m.base * rock);
    }
  }
}

}  // namespace yardsim::bench
