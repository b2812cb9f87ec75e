// The pair filter: masks, owners, ignored owner pairs and object pairs, symmetry.
#include "collision/collision_filter.hpp"

#include <catch2/catch.hpp>

using namespace yardsim::collision;

TEST_CASE("collision: groups and masks: both directions must accept") {
  CollisionFilter f;
  constexpr std::uint32_t kBody = 1u, kRope = 2u;
  f.setEntry(0, {-1, kBody, kAllGroups});
  f.setEntry(1, {-1, kRope, kBody});  // a rope segment sees bodies only
  f.setEntry(2, {-1, kRope, kBody});
  CHECK(f.canCollide(0, 1));
  CHECK(f.canCollide(1, 0));
  CHECK_FALSE(f.canCollide(1, 2));    // rope vs rope: masked out
  f.setEntry(3, {-1, kBody, kBody});  // a body that ignores ropes
  CHECK_FALSE(f.canCollide(3, 1));
  CHECK(f.canCollide(3, 0));
  CHECK_FALSE(f.canCollide(0, 0));
}

TEST_CASE("collision: same owner never collides, ignored owners and objects are symmetric") {
  CollisionFilter f;
  f.setEntry(0, {7, 1u, kAllGroups});   // rope 7, segment 0
  f.setEntry(1, {7, 1u, kAllGroups});   // rope 7, segment 1
  f.setEntry(2, {3, 1u, kAllGroups});   // body 3 (the hook block the rope is attached to)
  f.setEntry(3, {4, 1u, kAllGroups});   // body 4
  f.setEntry(4, {-1, 1u, kAllGroups});  // unowned
  f.setEntry(5, {-1, 1u, kAllGroups});  // unowned
  CHECK_FALSE(f.canCollide(0, 1));
  CHECK(f.canCollide(4, 5));  // two unowned objects are not "the same owner"
  CHECK(f.canCollide(0, 2));
  f.ignoreOwners(3, 7);
  CHECK_FALSE(f.canCollide(0, 2));
  CHECK_FALSE(f.canCollide(2, 1));
  CHECK(f.canCollide(0, 3));
  f.ignoreObjects(3, 0);
  CHECK_FALSE(f.canCollide(0, 3));
  CHECK(f.canCollide(1, 3));
  CHECK_THROWS(f.ignoreOwners(-1, 2));
}
