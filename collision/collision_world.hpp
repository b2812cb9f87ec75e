#pragma once
// The collision world of one scene: every shape and rope segment as an object with an id, one
// broad phase over all of them (FCL's dynamic AABB tree, behind a pimpl: no FCL type here), and
// the queries (world_queries.cpp): boolean interference, contact points, minimum distance with
// witness points, and clearance watches that query only the pairs within a margin. The FCL side
// is a module, libyardsim_fcl.so, opened with the first world of a process (world_backend.hpp).
//
// Motion: setPose / setSegment store the new pose and mark the object dirty; update() computes
// the tight world boxes of the dirty objects only and moves only their leaves in the tree (every
// query calls update() first). A pose is checked before it is stored: a non-finite value or a
// matrix that is not a rotation is refused with a CollisionError naming the object (a NaN in
// FCL's tree crashes it).
//
// Frames and units: X_WB is the pose of the object's body frame B in the world W; points p_W and
// normals n_W in the world frame; m. Objects are added at assembly and never removed.
// Not thread-safe: the queries reuse the world's scratch (no allocation after warm-up).
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "collision/collision_filter.hpp"
#include "collision/shape.hpp"

namespace yardsim::collision {

struct ObjectOptions {
  std::string name;    // for messages; default "object <id>"
  FilterEntry filter;  // owner, group, mask (collision_filter.hpp)
};

struct WorldOptions {
  // true: the broad phase uses the tight boxes of shape.hpp; false: FCL's own (a sphere around
  // the local box), kept for comparison in tests and benchmarks
  bool tightAabb = true;
  // the GJK used for convex pairs without a closed form (capsule-box, cylinder-box, box-box
  // distance): false libccd (default), true FCL's own GST_INDEP, which in FCL 0.7 returns wrong
  // box-box distances for some poses (world_queries_test: 0.1370 m for an exact 0.1275 m)
  bool independentGjk = false;
  // contacts(): a pair whose two objects have not been moved (setPose / setSegment) since the last
  // contacts() query with the same limit gets last query's contacts without a narrow phase
  bool reuseUnmovedPairs = true;
};

// One contact point between objects a and b (a < b).
struct Contact {
  ObjectId a = -1;
  ObjectId b = -1;
  Vector3 p_W = Vector3::Zero();   // contact point, m
  Vector3 n_W = Vector3::UnitZ();  // unit normal pointing from a towards b
  double depth = 0.0;              // penetration depth, m (>= 0)
};

// The minimum distance between two objects and the closest points on each.
struct Distance {
  ObjectId a = -1;
  ObjectId b = -1;
  double distance = 0.0;           // m; <= 0 when they touch or overlap (signed where FCL can)
  Vector3 pa_W = Vector3::Zero();  // witness point on a, m
  Vector3 pb_W = Vector3::Zero();  // witness point on b, m
};

// The closest approach within one watch.
struct Clearance {
  bool withinMargin = false;  // false: no pair closer than the margin (distance is a lower bound)
  Distance closest;           // the closest pair; distance = margin when !withinMargin
  int pairsQueried = 0;       // narrow-phase distance calls this time
};

// Counters of the last query, for benchmarks and tests.
struct QueryStats {
  int broadPhasePairs = 0;  // pairs whose boxes overlap (before the filter)
  int candidatePairs = 0;   // of those, pairs the filter lets through
  int narrowPhaseCalls = 0;
  int reusedPairs = 0;  // contacts(): pairs answered from the last query (nothing moved)
  int contacts = 0;
};

// The FCL side of the process: worlds (one FCL broad-phase manager each) and FCL collision
// objects (one per object, one query probe per world), made since the process started and alive
// now. Counted when they are made and destroyed, never by a query: for tests ("a scene without
// collision builds no FCL object", docs/collision.md).
struct FclCounts {
  long worldsMade = 0, worldsAlive = 0, objectsMade = 0, objectsAlive = 0;
};
// () => the counts now (all zero while no world has opened the FCL module)
FclCounts fclCounts();

class WorldBackend;

class CollisionWorld {
 public:
  explicit CollisionWorld(WorldOptions options = {});
  ~CollisionWorld();
  CollisionWorld(CollisionWorld&&) noexcept;
  CollisionWorld& operator=(CollisionWorld&&) noexcept;
  CollisionWorld(const CollisionWorld&) = delete;
  CollisionWorld& operator=(const CollisionWorld&) = delete;

  // (shape, X_WB, options) => a new object's id (0, 1, ...); throws CollisionError for a shape
  // checkShape refuses or a bad pose
  ObjectId add(const Shape& shape, const Transform& X_WB, const ObjectOptions& options = {});
  // (ends p0_W, p1_W, rope diameter m, options) => a rope segment: a capsule of radius d / 2
  ObjectId addSegment(const Vector3& p0_W, const Vector3& p1_W, double diameter,
                      const ObjectOptions& options = {});
  // (path points p_W, diameter, options) => one segment per span, all with options' owner
  // (give the rope an owner >= 0 so that its segments never collide with each other)
  std::vector<ObjectId> addRope(const std::vector<Vector3>& path_W, double diameter,
                                const ObjectOptions& options);

  // (id, X_WB) => stored and marked dirty; CollisionError naming the object if not finite or
  // not a rotation
  void setPose(ObjectId id, const Transform& X_WB);
  // (segment id, new ends) => stored and marked dirty; CollisionError if not finite
  void setSegment(ObjectId id, const Vector3& p0_W, const Vector3& p1_W);
  // (segment ids from addRope, new path with ids.size() + 1 points) => setSegment for each span
  void setRopePath(const std::vector<ObjectId>& ids, const std::vector<Vector3>& path_W);
  // () => the dirty objects' boxes recomputed and their leaves moved (new objects inserted)
  void update();

  int size() const;
  const std::string& name(ObjectId id) const;
  const Shape& shape(ObjectId id) const;
  // (id) => its pose (a segment: centre, z along p0 -> p1)
  const Transform& pose(ObjectId id) const;
  // (id) => the world box the broad phase holds for it (after update())
  Aabb aabb(ObjectId id) const;
  CollisionFilter& filter();
  const CollisionFilter& filter() const;

  // --- queries (world_queries.cpp); each calls update() first ---
  // () => pairs a < b whose boxes overlap and that pass the filter, in no particular order
  const std::vector<std::pair<ObjectId, ObjectId>>& candidatePairs();
  // () => whether any candidate pair intersects (stops at the first)
  bool anyInterference();
  // (at most this many points per pair) => all contact points of all intersecting candidate
  // pairs; pairs whose objects did not move since the last call keep their contacts
  // (WorldOptions::reuseUnmovedPairs). The reference stays valid until the next call.
  const std::vector<Contact>& contacts(int maxPerPair = 4);
  // (a, b) => minimum distance and witness points (no filter, no broad phase); capsule-box
  // exact (segment_box.hpp), other pairs by FCL
  Distance distance(ObjectId a, ObjectId b);
  // (a, b) => whether the two intersect (no filter)
  bool intersects(ObjectId a, ObjectId b);

  // (sets a and b, margin m) => a watch id: clearance(w) reports the closest pair between the
  // sets, querying only pairs whose boxes, grown by the margin, overlap and that the filter lets
  // through
  int addWatch(std::vector<ObjectId> a, std::vector<ObjectId> b, double margin);
  const Clearance& clearance(int watch);

  const QueryStats& stats() const;

  struct Impl;  // opaque: the FCL side (collision/detail/world_impl.hpp, private to collision/)

 private:
  std::unique_ptr<WorldBackend> backend_;  // in the module libyardsim_fcl.so (world_backend.hpp)
};

}  // namespace yardsim::collision
