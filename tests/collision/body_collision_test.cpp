// BodyCollision's readings of a clearance watch against hand computation, and its memory of the
// last two states read: a watch read again at poses it was read at gives what a fresh world gives
// there, and poses never read (an integrator's stages) are queried afresh, never taken from a
// slot of other poses.
#include <catch2/catch.hpp>

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
