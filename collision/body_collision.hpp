#pragma once
// The collision objects of one mechanical system, driven by its bodies: each colliding body's
// shapes sit at fixed poses X_BS in its body frame (the world's own shapes, the ground, in the
// world frame), ropes are capsules along the straight spans between their path points (ends and
// sheave centres, on bodies). Two worlds, each with only what it needs: the contact world holds
// the bodies' shapes (contact points for forces::ContactForce), the clearance world holds the
// bodies and ropes that clearance watches name (minimum distances with witness points).
//
// Filtering by rule: a body never collides with itself (its shapes share an owner), nor the
// world's shapes with each other; a rope never with the bodies it is attached to; and the body
// pairs of `ignore` (the caller lists jointed bodies and what the scene ignores), and each shape's
// and rope's group bits and mask (collision_filter.hpp). Materials: each
// shape has a material index; the pair (m_a, m_b) picks a contact law index from the pair table.
//
// Frames and units: X_WB from dynamics::Data (body pose in the world W), X_BS shape frame in
// the body frame B, points and normals in W, m. Not thread-safe (the worlds reuse scratch).
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "collision/collision_world.hpp"
#include "dynamics/data.hpp"
#include "forces/contact.hpp"

namespace yardsim::collision {

// One shape on a body (body 0: the world).
struct BodyShape {
  int body = 0;
  std::string name;  // for messages and reports: the body's name
  Shape shape;
  Transform X_BS = Transform::identity();
  int material = 0;  // index into the material names of the spec
  // the filter's group bits and mask (collision_filter.hpp), in both worlds
  std::uint32_t group = 1, mask = kAllGroups;
};

// A rope: its path points on bodies (body index, p_B m), its diameter (m).
struct RopeShape {
  std::string name;
  std::vector<std::pair<int, Vector3>> path;
  double diameter = 0.0;
  std::uint32_t group = 1, mask = kAllGroups;  // as BodyShape's (clearance world)
};

// A clearance watch: the closest approach between the objects named in a and in b (body or
// rope names resolved by the caller into indices of shapes and ropes), and its threshold.
struct ClearanceSpec {
  std::string name;
  std::vector<int> shapesA, ropesA, shapesB, ropesB;  // indices into shapes / ropes
  double below = 0.0;                                 // m, the clearance_below threshold
  double margin = 0.0;  // m, >= below: distances beyond it are not computed (reported as margin)
};

struct BodyCollisionSpec {
  std::vector<BodyShape> shapes;
  std::vector<RopeShape> ropes;
  int bodyCount = 1;  // the model's bodies (with the world)
  // owner pairs never tested (jointed bodies, ...): body indices, a rope r as bodyCount + r
  std::vector<std::pair<int, int>> ignore;
  int materialCount = 1;     // material names
  std::vector<int> pairLaw;  // [m_a * materialCount + m_b] => law index
  std::vector<ClearanceSpec> watches;
  int maxPointsPerPair = 4;
  // false: no contact world (only the clearance watches): contacts() gives nothing
  bool contact = true;
  // the ground: the half-space z <= groundHeight (world), contact computed here, not by FCL:
  // a point at every vertex of a box or mesh below it, the lowest point of a sphere and of a
  // capsule's end spheres, 16 points on each rim of a cylinder (FCL gives one point for a face
  // on a plane, which rocks a resting block)
  bool ground = false;
  double groundHeight = 0.0;  // m
  int groundMaterial = 0;
};

// The closest approach of one watch at the last update, with the pair's names.
struct WatchReading {
  double distance = 0.0;  // m (the watch's margin when nothing is closer)
  std::string a, b;       // the closest pair's names ("" when nothing within the margin)
  Vector3 pa_W = Vector3::Zero(), pb_W = Vector3::Zero();  // witness points, m
};

class BodyCollision {
 public:
  // (spec, kinematics at the start) => the worlds built; CollisionError naming a bad shape
  BodyCollision(BodyCollisionSpec spec, const dynamics::Data& kin);

  // (kinematics) => every object moved to its body's pose and every rope to its path
  void update(const dynamics::Data& kin);
  // (after update) => the contact points between bodies, appended to out, with the pair's law
  void contacts(std::vector<forces::ContactPoint>& out);
  // (after update) => the deepest point of any body below the ground, m (> 0 in the ground, < 0
  // above it: minus the smallest height over it); -infinity without a ground
  double groundPenetration() const;
  // (after update, watch) => its closest approach
  WatchReading clearance(std::size_t watch);

  const BodyCollisionSpec& spec() const { return spec_; }
  const CollisionWorld& contactWorld() const { return contact_; }

 private:
  // (shape, its world pose) => its contact points with the ground, appended to out
  void groundContacts(const BodyShape& s, const Transform& X_WS,
                      std::vector<forces::ContactPoint>& out) const;
  // (rope, body poses X_WB) => its path points in the world, in scratch_
  const std::vector<Vector3>& ropePath(const RopeShape& r, const std::vector<Transform>& X_WB);

  BodyCollisionSpec spec_;
  CollisionWorld contact_, clearance_;
  std::vector<ObjectId> contactIds_;                     // per shape
  std::vector<ObjectId> clearanceShapeIds_;              // per shape, -1 if not watched
  std::vector<std::vector<ObjectId>> clearanceRopeIds_;  // per rope, empty if not watched
  std::vector<int> clearanceOwnerName_;  // per clearance object: shape index, or -1 - rope index
  std::vector<int> watchIds_;
  std::vector<Vector3> scratch_;
  // The poses of the last update (per body index). The contact world is moved at every update
  // (forces need it at every stage); the clearance world only when a watch is read at poses it
  // is not at (event functions and channels read the committed states, not the stages).
  std::vector<Transform> X_WB_;
  bool posed_ = false;
  bool clearancePosed_ = false;  // the clearance world is at X_WB_
  // What was read at the poses of the last two states that were read (the locator asks for the
  // event functions at the start of a step, the end of the previous one, again): the readings of
  // each watch per pose set; a slot is matched by exact equality of poses.
  struct ReadSlot {
    std::vector<Transform> X_WB;
    std::vector<char> valid;  // per watch
    std::vector<WatchReading> readings;
  };
  ReadSlot slots_[2];
  int slot_ = -1;     // the slot at X_WB_, or -1 (none yet)
  int lastRead_ = 0;  // the slot read last (the other one is replaced first)
  // () => the slot at X_WB_, made (replacing the one read least recently) when there is none
  ReadSlot& readSlot();
  std::vector<char> touchesGround_;  // per shape: not ignored with the world
  std::vector<std::vector<Vector3>>
      groundPoints_;  // per shape: the points tested against the ground, B
};

}  // namespace yardsim::collision
