// BodyCollision's readings of a clearance watch against hand computation, and its memory of the
// last two states read: a watch read again at poses it was read at gives what a fresh world gives
// there, and poses never read (an integrator's stages) are queried afresh, never taken from a
// slot of other poses. Shapes and ropes kept apart by group masks or by an ignored owner pair
// (a rope as bodyCount + its index) are never queried, in contact or in a watch.
#include <catch2/catch.hpp>

#include <set>
#include <tuple>

#include "collision/body_collision.hpp"
#include "dynamics/model_builder.hpp"

using namespace yardsim;
using namespace yardsim::collision;
using dynamics::Vector3;

namespace {

// (model) => a spec: a 2 m cube on body 1 and a vertical rope (diameter 0.04 m) on x = 0 from
// the world, watched within 5 m, threshold 1 m
BodyCollisionSpec ropeAndCart() {
  BodyCollisionSpec spec;
  spec.bodyCount = 2;
  spec.shapes.push_back({1, "cart", Shape::box(Vector3(2, 2, 2))});
  spec.ropes.push_back({"hoist", {{0, Vector3(0, 0, 10)}, {0, Vector3(0, 0, -10)}}, 0.04});
  spec.pairLaw = {0};
  spec.contact = false;
  spec.watches.push_back({"rope_cart", {}, {0}, {0}, {}, 1.0, 5.0});
  return spec;
}

// (data, x) => the cart's centre at (x, 0, 0)
void place(dynamics::Data& d, double x) {
  d.X_WB[1] = dynamics::Transform::identity();
  d.X_WB[1].p = Vector3(x, 0, 0);
}

}  // namespace

TEST_CASE("body collision: watch readings at poses read before equal a fresh world's") {
  dynamics::ModelBuilder b;
  b.addBody("cart", "world", dynamics::Joint::free(), {},
            dynamics::boxInertia(1000, Vector3(2, 2, 2)));
  const dynamics::Model m = b.build();
  dynamics::Data d(m);
  place(d, 3.0);
  BodyCollision world(ropeAndCart(), d);
  // (x) => the distance read after an update at x; by hand x - 1 - 0.02
  auto read = [&](double x) {
    place(d, x);
    world.update(d);
    return world.clearance(0).distance;
  };
  auto fresh = [&](double x) {
    place(d, x);
    BodyCollision other(ropeAndCart(), d);
    other.update(d);
    return other.clearance(0).distance;
  };
  CHECK(read(3.0) == Approx(1.98).margin(1e-12));
  CHECK(read(2.5) == Approx(1.48).margin(1e-12));
  // stages between the reads: moved, not read
  for (const double x : {2.7, 2.6, 2.55}) {
    place(d, x);
    world.update(d);
  }
  CHECK(read(3.0) == fresh(3.0));  // the step's start again: from its slot
  CHECK(read(2.5) == fresh(2.5));
  CHECK(read(2.2) == Approx(1.18).margin(1e-12));  // new poses: queried, not a slot's
  CHECK(read(2.0) == Approx(0.98).margin(1e-12));
  CHECK(read(2.2) == fresh(2.2));
  CHECK(read(1.5) == Approx(0.48).margin(1e-12));
  const WatchReading r = world.clearance(0);  // again at 1.5 m
  CHECK(r.a == "hoist");
  CHECK(r.b == "cart");
  CHECK(r.pb_W.x() == Approx(0.5).margin(1e-9));  // on the cart's face
}

TEST_CASE("body collision: shapes and ropes filtered by group and owner pairs are never queried") {
  // three free 1 m cubes, each 0.1 m into the next along x (bodies 1, 2, 3), and a rope beside
  // cube 3 (owner bodyCount + 0) watched against it
  dynamics::ModelBuilder b;
  for (const char* name : {"c1", "c2", "c3"})
    b.addBody(name, "world", dynamics::Joint::free(), {},
              dynamics::boxInertia(1000, Vector3(1, 1, 1)));
  const dynamics::Model m = b.build();
  dynamics::Data d(m);
  for (int i = 1; i <= 3; ++i) {
    d.X_WB[static_cast<std::size_t>(i)] = dynamics::Transform::identity();
    d.X_WB[static_cast<std::size_t>(i)].p = Vector3(0.9 * (i - 1), 0, 0);
  }
  // (group of c1, mask of c1, ignore the rope with c3) => narrow phases, contact pairs, the
  // watch's reading
  auto query = [&](std::uint32_t group1, std::uint32_t mask3, bool ignoreRope) {
    BodyCollisionSpec spec;
    spec.bodyCount = 4;
    for (int i = 1; i <= 3; ++i)
      spec.shapes.push_back({i, "c" + std::to_string(i), Shape::box(Vector3(1, 1, 1))});
    spec.shapes[0].group = group1;
    spec.shapes[2].mask = mask3;
    spec.ropes.push_back({"hoist", {{0, Vector3(2.3, 0, 5)}, {0, Vector3(2.3, 0, -5)}}, 0.04});
    spec.pairLaw = {0};
    spec.watches.push_back({"rope_c3", {}, {0}, {2}, {}, 0.5, 1.0});
    if (ignoreRope) spec.ignore.emplace_back(spec.bodyCount + 0, 3);
    BodyCollision world(std::move(spec), d);
    world.update(d);
    std::vector<forces::ContactPoint> points;
    world.contacts(points);
    std::set<std::pair<int, int>> pairs;
    for (const auto& p : points) pairs.insert({p.bodyA, p.bodyB});
    return std::tuple{world.contactWorld().stats().narrowPhaseCalls, pairs,
                      world.clearance(0).distance};
  };
  using Pairs = std::set<std::pair<int, int>>;
  // c1 and c2 overlap, c2 and c3 overlap (c1 and c3 are 0.8 m apart): two narrow phases
  const auto [n0, p0, w0] = query(1, kAllGroups, false);
  CHECK(n0 == 2);
  CHECK(p0 == Pairs{{1, 2}, {2, 3}});
  CHECK(w0 == Approx(-0.02).margin(1e-9));  // the rope's axis on c3's face x = 2.3: -d / 2
  // c1 in group bit 2, c3's mask without bit 0 (the group of c2 and the rope): c2-c3 and the
  // rope-c3 watch never reach a narrow phase, c1-c2 still does
  const auto [n2, p2, w2] = query(1u << 2, kAllGroups & ~1u, false);
  CHECK(n2 == 1);
  CHECK(p2 == Pairs{{1, 2}});
  CHECK(w2 == 1.0);  // nothing queried: the watch's margin
  // the rope and c3 as an ignored owner pair: the watch queries nothing (its margin)
  const auto [n3, p3, w3] = query(1, kAllGroups, true);
  CHECK(w3 == 1.0);
  CHECK(p3 == Pairs{{1, 2}, {2, 3}});
}
