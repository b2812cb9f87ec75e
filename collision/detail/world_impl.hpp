#pragma once
// Private to collision/: the FCL side of CollisionWorld (the module libyardsim_fcl.so), shared by
// fcl_world.cpp (objects, poses, broad phase) and world_queries.cpp (queries). Not part of
// the API: no header outside collision/*.cpp includes it.
#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>
#include <fcl/narrowphase/distance.h>

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "collision/collision_world.hpp"
#include "collision/pair_cache.hpp"
#include "collision/world_backend.hpp"

namespace yardsim::collision::detail {

// How many of one kind of FCL thing were made and are alive, process-wide (fclCounts()).
struct Tally {
  std::atomic<long> made{0}, alive{0};
};
inline Tally worldTally, objectTally;

// A member that counts its owner in a tally: when it is made (or copied) and destroyed only.
template <Tally& T>
struct Counted {
  Counted() {
    ++T.made;
    ++T.alive;
  }
  Counted(const Counted&) : Counted() {}
  Counted& operator=(const Counted&) { return *this; }
  ~Counted() { --T.alive; }
};

// An FCL object whose world box we set ourselves (CollisionObject keeps it in a protected
// member and only knows how to compute its loose default).
class FclObject : public fcl::CollisionObjectd {
 public:
  using fcl::CollisionObjectd::CollisionObjectd;
  // (box) => the box the broad phase will use
  void setAabb(const Aabb& b) {
    aabb.min_ = b.min;
    aabb.max_ = b.max;
  }

 private:
  Counted<objectTally> counted_;
};

struct Record {
  std::string name;
  Shape shape;
  ShapeBound bound;
  Transform X_WB;
  bool segment = false;  // a rope segment: shape is a capsule between p0_W and p1_W
  Vector3 p0_W = Vector3::Zero();
  Vector3 p1_W = Vector3::Zero();
  std::shared_ptr<fcl::CollisionGeometryd> geometry;
  std::unique_ptr<FclObject> object;
  Aabb box;
  bool dirty = true;
  bool registered = false;
  std::uint64_t version = 0;  // pose updates so far (PairCache)
};

struct Watch {
  std::vector<ObjectId> a;
  std::vector<std::uint8_t> inB;  // one flag per object: a member of set b
  double margin = 0.0;
  Clearance result;
};

// (pointer) => the id stored as FCL user data
inline ObjectId idOf(const fcl::CollisionObjectd* o) {
  return static_cast<ObjectId>(reinterpret_cast<std::intptr_t>(o->getUserData()));
}

}  // namespace yardsim::collision::detail

namespace yardsim::collision {

struct CollisionWorld::Impl {
  detail::Counted<detail::worldTally> counted;  // one FCL broad-phase manager
  WorldOptions options;
  std::vector<detail::Record> records;
  std::vector<ObjectId> dirty;    // poses changed since the last update()
  std::vector<ObjectId> pending;  // added, not yet in the tree
  fcl::DynamicAABBTreeCollisionManagerd manager;
  CollisionFilter filter;
  std::unordered_map<const forces::TriangleMesh*, std::shared_ptr<fcl::BVHModel<fcl::OBBRSSd>>>
      meshes;  // one BVH per mesh, shared by the objects that use it
  std::vector<detail::Watch> watches;
  std::unique_ptr<detail::FclObject> probe;  // a query box for the watches

  // scratch, kept between queries so that the step loop does not allocate after warm-up
  std::vector<fcl::CollisionObjectd*> moved;
  std::vector<fcl::CollisionObjectd*> added;
  std::vector<std::pair<ObjectId, ObjectId>> pairs;
  std::vector<Contact> contacts;
  fcl::CollisionRequestd request;
  fcl::CollisionResultd result;
  fcl::DistanceRequestd distanceRequest;
  fcl::DistanceResultd distanceResult;
  QueryStats stats;
  PairCache pairCache;  // contacts of pairs that did not move (WorldOptions::reuseUnmovedPairs)

  // (record) => its FCL transform and world box from X_WB
  void refresh(detail::Record& r) const;
  // (a, b) => whether their current boxes overlap. FCL's tree keeps a leaf's old box when the
  // new one fits inside it (HierarchyTree::update), so a leaf may be larger than its object:
  // every pair the tree reports is checked again against the exact boxes.
  bool boxesOverlap(ObjectId a, ObjectId b) const {
    return records[static_cast<std::size_t>(a)].box.overlaps(
        records[static_cast<std::size_t>(b)].box);
  }
  // (id) => the record, or std::out_of_range naming the id
  detail::Record& at(ObjectId id);
};

// The world on FCL's side: CollisionWorld's methods (fcl_world.cpp, world_queries.cpp) on its Impl
class FclWorld final : public WorldBackend {
 public:
  using Impl = CollisionWorld::Impl;
  explicit FclWorld(const WorldOptions& options);
  ObjectId add(const Shape& shape, const Transform& X_WB, const ObjectOptions& options) override;
  ObjectId addSegment(const Vector3& p0_W, const Vector3& p1_W, double diameter,
                      const ObjectOptions& options) override;
  std::vector<ObjectId> addRope(const std::vector<Vector3>& path_W, double diameter,
                                const ObjectOptions& options) override;
  void setPose(ObjectId id, const Transform& X_WB) override;
  void setSegment(ObjectId id, const Vector3& p0_W, const Vector3& p1_W) override;
  void setRopePath(const std::vector<ObjectId>& ids, const std::vector<Vector3>& path_W) override;
  void update() override;
  int size() const override;
  const std::string& name(ObjectId id) const override;
  const Shape& shape(ObjectId id) const override;
  const Transform& pose(ObjectId id) const override;
  Aabb aabb(ObjectId id) const override;
  CollisionFilter& filter() override;
  const CollisionFilter& filter() const override;
  const std::vector<std::pair<ObjectId, ObjectId>>& candidatePairs() override;
  bool anyInterference() override;
  const std::vector<Contact>& contacts(int maxPerPair) override;
  Distance distance(ObjectId a, ObjectId b) override;
  bool intersects(ObjectId a, ObjectId b) override;
  int addWatch(std::vector<ObjectId> a, std::vector<ObjectId> b, double margin) override;
  const Clearance& clearance(int watch) override;
  const QueryStats& stats() const override;

 private:
  std::unique_ptr<Impl> impl_;
};

// (world, a, b) => fcl::collide into m.result, a mesh first; the sign that makes normals a -> b
double collideOrdered(CollisionWorld::Impl& m, ObjectId a, ObjectId b);

}  // namespace yardsim::collision
