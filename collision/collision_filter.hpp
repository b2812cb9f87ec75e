#pragma once
// Which pairs of collision objects are tested at all, by rule, before any narrow phase:
//  - groups and masks (32-bit fields): a and b are tested only if (group_a & mask_b) and
//    (group_b & mask_a) are both non-zero (e.g. a "rope" group whose mask leaves out other ropes);
//  - owners: objects with the same owner never collide (the segments of one rope, the parts of
//    one body); an owner is an integer the caller chooses (a body index, a rope index), < 0 for
//    "this object alone";
//  - ignored owner pairs: a rope and each body it is attached to, a body and its parent joint's
//    body, and what a scene lists under collision: {ignore: [[a, b], ...]} (the scene maps the
//    names to owners);
//  - ignored object pairs, for a single part of a body.
// The rules are symmetric. Lookups are O(1) (hash sets); the world calls canCollide for every
// candidate pair of the broad phase.
#include <cstdint>
#include <unordered_set>
#include <vector>

namespace yardsim::collision {

using ObjectId = int;

inline constexpr std::uint32_t kAllGroups = 0xffffffffu;

// An object's filtering data; the world fills it from the object's options.
struct FilterEntry {
  int owner = -1;  // < 0: owned by nobody else
  std::uint32_t group = 1;
  std::uint32_t mask = kAllGroups;
};

class CollisionFilter {
 public:
  // (id, entry) => sets (or grows the table to) object id's entry
  void setEntry(ObjectId id, const FilterEntry& entry);
  const FilterEntry& entry(ObjectId id) const { return entries_.at(static_cast<std::size_t>(id)); }

  // (owner a, owner b) => pairs across these two owners are never tested (a == b is implied)
  void ignoreOwners(int ownerA, int ownerB);
  // (object a, object b) => this one pair is never tested
  void ignoreObjects(ObjectId a, ObjectId b);

  // (a, b) => whether the pair passes every rule; a == b never does
  bool canCollide(ObjectId a, ObjectId b) const;

 private:
  // (x, y) => one key for the unordered pair
  static std::uint64_t key(int x, int y);

  std::vector<FilterEntry> entries_;
  std::unordered_set<std::uint64_t> ignoredOwners_;
  std::unordered_set<std::uint64_t> ignoredObjects_;
};

}  // namespace yardsim::collision
