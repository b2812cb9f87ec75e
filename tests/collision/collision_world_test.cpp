// The world: poses refused when not finite, tight boxes against FCL's default (fewer candidate
// pairs on rotated boxes, and exactly the pairs whose boxes overlap), incremental updates against
// a full rebuild, and the filter in the broad phase.
#include "collision/collision_world.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "forces/geometry/primitive_meshes.hpp"

using namespace yardsim::collision;
using yardsim::dynamics::Matrix3;
using Pairs = std::vector<std::pair<ObjectId, ObjectId>>;

namespace {

Matrix3 randomRotation(std::mt19937& rng) {
  std::normal_distribution<double> n;
  Eigen::Quaterniond q(n(rng), n(rng), n(rng), n(rng));
  q.normalize();
  return q.toRotationMatrix();
}

Vector3 randomPoint(std::mt19937& rng, double extent) {
  std::uniform_real_distribution<double> u(0.0, extent);
  return Vector3(u(rng), u(rng), u(rng));
}

Pairs sorted(Pairs p) {
  std::sort(p.begin(), p.end());
  return p;
}

// A mixed scene: what to add, and the poses it ends with.
struct Item {
  Shape shape;
  bool segment = false;
  Transform X;
  Vector3 p0 = Vector3::Zero(), p1 = Vector3::Zero();
};

// (items, tight) => a world holding them at their current poses
CollisionWorld build(const std::vector<Item>& items, bool tight = true) {
  CollisionWorld w(WorldOptions{tight, false});
  for (const Item& it : items) {
    if (it.segment)
      w.addSegment(it.p0, it.p1, 2.0 * it.shape.radius);
    else
      w.add(it.shape, it.X);
  }
  return w;
}

}  // namespace

TEST_CASE("collision: a non-finite pose is refused with the object's name, before it reaches FCL") {
  CollisionWorld w;
  const ObjectId a = w.add(Shape::box(Vector3(1, 1, 1)), Transform::identity(), {"block A", {}});
  const ObjectId s = w.addSegment(Vector3(0, 0, 5), Vector3(0, 0, 9), 0.05, {"hoist", {}});
  Transform bad = Transform::translation(Vector3(0, std::nan(""), 0));
  CHECK_THROWS_WITH(w.setPose(a, bad), Catch::Contains("block A") && Catch::Contains("non-finite"));
  bad = Transform::identity();
  bad.R(0, 0) = INFINITY;
  CHECK_THROWS_AS(w.setPose(a, bad), CollisionError);
  CHECK_THROWS_WITH(w.setSegment(s, Vector3(0, 0, NAN), Vector3::Zero()), Catch::Contains("hoist"));
  Transform scaled = Transform::identity();
  scaled.R *= 2.0;
  CHECK_THROWS_WITH(w.setPose(a, scaled), Catch::Contains("not a rotation"));
  CHECK_THROWS_AS(w.add(Shape::sphere(1.0), Transform::translation(Vector3(NAN, 0, 0))),
                  CollisionError);
  // the world is still usable and holds the last good poses
  CHECK(w.candidatePairs().empty());
  CHECK(w.aabb(a).max.x() == Approx(0.5));
}

TEST_CASE(
    "collision: a box or a position beyond 1e12 m is refused with the object's name, before FCL") {
  // (tests/fuzz/mutate.py: a box of 1e300 m, or a centre of mass at 1e300 m, crashed FCL's tree
  // balancing with a segmentation fault)
  CollisionWorld huge;
  huge.add(Shape::box(Vector3(1, 1, 1)), Transform::identity(), {"block A", {}});
  huge.add(Shape::box(Vector3(1, 1e300, 1)), Transform::identity(), {"loader", {}});
  CHECK_THROWS_WITH(huge.candidatePairs(),
                    Catch::Contains("'loader'") && Catch::Contains("beyond 1e12 m"));
  CollisionWorld far;
  far.add(Shape::box(Vector3(1, 1, 1)), Transform::identity(), {"block A", {}});
  far.add(Shape::sphere(1.0), Transform::translation(Vector3(0, 0, 1e300)), {"ball", {}});
  CHECK_THROWS_WITH(far.candidatePairs(), Catch::Contains("'ball'"));
  CollisionWorld fine;  // (1e6 m: a large yard, still fine)
  fine.add(Shape::box(Vector3(1, 1, 1)), Transform::identity(), {"block A", {}});
  fine.add(Shape::sphere(1.0), Transform::translation(Vector3(1e6, 0, 0)), {"ball", {}});
  CHECK(fine.candidatePairs().empty());
}

TEST_CASE(
    "collision: tight boxes give exactly the overlapping corner-box pairs, fewer than FCL "
    "default") {
  std::mt19937 rng(11);
  std::vector<Item> items;
  for (int i = 0; i < 600; ++i) {
    items.push_back({Shape::box(Vector3(6.0, 1.0, 0.4)), false,
                     Transform{randomRotation(rng), randomPoint(rng, 60.0)}, Vector3::Zero(),
                     Vector3::Zero()});
  }
  CollisionWorld tight = build(items, true), loose = build(items, false);
  const Pairs pt = sorted(tight.candidatePairs()), pl = sorted(loose.candidatePairs());
  // independent: the boxes of the eight corners, all pairs
  std::vector<Aabb> boxes;
  for (const Item& it : items) {
    Aabb b{Vector3::Constant(1e9), Vector3::Constant(-1e9)};
    for (int c = 0; c < 8; ++c) {
      const Vector3 p =
          it.X.actPoint(Vector3(c & 1 ? 3.0 : -3.0, c & 2 ? 0.5 : -0.5, c & 4 ? 0.2 : -0.2));
      b.min = b.min.cwiseMin(p);
      b.max = b.max.cwiseMax(p);
    }
    boxes.push_back(b);
  }
  Pairs brute;
  for (int i = 0; i < 600; ++i)
    for (int j = i + 1; j < 600; ++j)
      if (boxes[i].overlaps(boxes[j])) brute.emplace_back(i, j);
  CHECK(pt == brute);
  INFO("tight " << pt.size() << ", FCL default " << pl.size());
  CHECK(pl.size() > 2 * pt.size());  // FCL's sphere-sized box of a 6 x 1 x 0.4 plank is loose
  CHECK(std::includes(pl.begin(), pl.end(), pt.begin(), pt.end()));
}

TEST_CASE("collision: incremental updates give the same candidate pairs as a full rebuild") {
  auto mesh = std::make_shared<yardsim::forces::TriangleMesh>(
      yardsim::forces::cylinderMesh(1.5, -2.0, 2.0, 16));
  for (unsigned seed : {1u, 2u, 3u, 4u}) {
    std::mt19937 rng(seed);
    std::vector<Item> items;
    for (int i = 0; i < 400; ++i) {
      const Transform X{randomRotation(rng), randomPoint(rng, 50.0)};
      switch (i % 6) {
        case 0:
          items.push_back(
              {Shape::box(Vector3(3, 2, 1)), false, X, Vector3::Zero(), Vector3::Zero()});
          break;
        case 1:
          items.push_back({Shape::sphere(1.2), false, X, Vector3::Zero(), Vector3::Zero()});
          break;
        case 2:
          items.push_back({Shape::cylinder(0.8, 3.0), false, X, Vector3::Zero(), Vector3::Zero()});
          break;
        case 3:
          items.push_back({Shape::capsule(0.5, 2.0), false, X, Vector3::Zero(), Vector3::Zero()});
          break;
        case 4:
          items.push_back({Shape::triangleMesh(mesh), false, X, Vector3::Zero(), Vector3::Zero()});
          break;
        default: {
          const Vector3 p0 = randomPoint(rng, 50.0);
          items.push_back({Shape::capsule(0.05, 0.0), true, X, p0, p0 + randomPoint(rng, 8.0)});
        }
      }
    }
    CollisionWorld w = build(items);
    w.candidatePairs();
    std::uniform_int_distribution<int> pick(0, 399);
    for (int step = 0; step < 25; ++step) {
      for (int k = 0; k < 40; ++k) {  // 10 % moving
        const int i = pick(rng);
        Item& it = items[static_cast<std::size_t>(i)];
        if (it.segment) {
          it.p0 += randomPoint(rng, 2.0) - Vector3::Constant(1.0);
          w.setSegment(i, it.p0, it.p1);
        } else {
          it.X = Transform{randomRotation(rng),
                           it.X.p + randomPoint(rng, 4.0) - Vector3::Constant(2.0)};
          w.setPose(i, it.X);
        }
      }
      if (step % 5 == 4) {
        CollisionWorld fresh = build(items);
        const Pairs a = sorted(w.candidatePairs()), b = sorted(fresh.candidatePairs());
        INFO("seed " << seed << " step " << step);
        CHECK(a.size() > 0);
        CHECK(a == b);
        if (a != b) {
          Pairs d1, d2;
          std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(d1));
          std::set_difference(b.begin(), b.end(), a.begin(), a.end(), std::back_inserter(d2));
          for (auto [i, j] : d1)
            WARN("only incremental " << i << " " << j << " overlap "
                                     << w.aabb(i).overlaps(w.aabb(j))
                                     << fresh.aabb(i).overlaps(fresh.aabb(j)));
          for (auto [i, j] : d2)
            WARN("only fresh " << i << " " << j << " overlap " << w.aabb(i).overlaps(w.aabb(j))
                               << fresh.aabb(i).overlaps(fresh.aabb(j)));
        }
      }
    }
  }
}

TEST_CASE("collision: the filter removes pairs in the broad phase") {
  CollisionWorld w;
  ObjectOptions body{"body", {1, 1u, kAllGroups}};
  const ObjectId a = w.add(Shape::box(Vector3(2, 2, 2)), Transform::identity(), body);
  const ObjectId b =
      w.add(Shape::box(Vector3(2, 2, 2)), Transform::translation(Vector3(1, 0, 0)), body);
  const ObjectId c = w.add(Shape::sphere(1.0), Transform::translation(Vector3(0, 1.5, 0)),
                           {"ball", {2, 1u, kAllGroups}});
  const auto rope = w.addRope({Vector3(0, 0, 0.5), Vector3(0, 0, 5), Vector3(3, 0, 9)}, 0.1,
                              {"rope", {3, 2u, 1u}});
  // a-b same owner; a-c, b-c touch; the rope's first segment starts inside a and b
  Pairs p = sorted(w.candidatePairs());
  CHECK(std::find(p.begin(), p.end(), std::pair{a, b}) == p.end());
  CHECK(std::find(p.begin(), p.end(), std::pair{a, c}) != p.end());
  CHECK(std::find(p.begin(), p.end(), std::pair{a, rope[0]}) != p.end());
  CHECK(std::find(p.begin(), p.end(), std::pair{rope[0], rope[1]}) == p.end());  // same rope
  w.filter().ignoreOwners(1, 3);  // the rope is attached to body 1
  w.filter().ignoreOwners(1, 2);  // collision: {ignore: [[body, ball]]}
  p = sorted(w.candidatePairs());
  CHECK(p.empty());
  CHECK(w.stats().broadPhasePairs >= 4);
  CHECK_FALSE(w.anyInterference());
}

TEST_CASE("collision: FCL's default boxes still bound a half-space finitely") {
  CollisionWorld w(WorldOptions{false, false, false});
  w.add(Shape::halfSpace(Vector3::UnitZ(), 0.0), Transform::identity());
  const ObjectId s = w.add(Shape::sphere(0.5), Transform::translation(Vector3(3, 4, 0.4)));
  CHECK(w.aabb(0).max.z() == 0.0);
  CHECK(std::isfinite(w.aabb(0).min.x()));
  CHECK(w.candidatePairs().size() == 1);
  w.setPose(s, Transform::translation(Vector3(3, 4, 0.6)));
  CHECK(w.candidatePairs().empty());
}

TEST_CASE("collision: the FCL counts follow worlds and objects made and destroyed") {
  const FclCounts before = fclCounts();
  {
    CollisionWorld world;  // one manager and its query probe
    FclCounts now = fclCounts();
    CHECK(now.worldsMade == before.worldsMade + 1);
    CHECK(now.worldsAlive == before.worldsAlive + 1);
    CHECK(now.objectsAlive == before.objectsAlive + 1);
    world.add(Shape::box(Vector3(1, 1, 1)), Transform::identity());
    world.addRope({Vector3(0, 0, 5), Vector3(0, 0, 2), Vector3(3, 0, 2)}, 0.04, {"rope", {7}});
    now = fclCounts();
    CHECK(now.objectsMade == before.objectsMade + 4);  // probe, box, two segments
    CHECK(now.objectsAlive == before.objectsAlive + 4);
    // queries make no FCL object
    world.contacts(4);
    world.candidatePairs();
    CHECK(fclCounts().objectsMade == now.objectsMade);
    CollisionWorld moved(std::move(world));  // the same objects, not new ones
    CHECK(fclCounts().worldsMade == now.worldsMade);
    CHECK(fclCounts().objectsMade == now.objectsMade);
  }
  const FclCounts after = fclCounts();
  CHECK(after.worldsAlive == before.worldsAlive);
  CHECK(after.objectsAlive == before.objectsAlive);
  CHECK(after.worldsMade == before.worldsMade + 1);
}
