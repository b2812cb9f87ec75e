#include "collision/collision_filter.hpp"

#include <algorithm>
#include <stdexcept>

namespace yardsim::collision {

// (x, y) => min in the high word, max in the low word
std::uint64_t CollisionFilter::key(int x, int y) {
  const auto lo = static_cast<std::uint32_t>(std::min(x, y));
  const auto hi = static_cast<std::uint32_t>(std::max(x, y));
  return (static_cast<std::uint64_t>(lo) << 32) | hi;
}

// (id, entry) => stored
void CollisionFilter::setEntry(ObjectId id, const FilterEntry& entry) {
  if (id < 0) throw std::invalid_argument("CollisionFilter: negative object id");
  if (static_cast<std::size_t>(id) >= entries_.size()) {
    entries_.resize(static_cast<std::size_t>(id) + 1);
  }
  entries_[static_cast<std::size_t>(id)] = entry;
}

// (owner a, owner b) => remembered
void CollisionFilter::ignoreOwners(int ownerA, int ownerB) {
  if (ownerA < 0 || ownerB < 0) throw std::invalid_argument("CollisionFilter: negative owner");
  ignoredOwners_.insert(key(ownerA, ownerB));
}

// (a, b) => remembered
void CollisionFilter::ignoreObjects(ObjectId a, ObjectId b) {
  if (a < 0 || b < 0) throw std::invalid_argument("CollisionFilter: negative object id");
  ignoredObjects_.insert(key(a, b));
}

// (a, b) => masks, same owner, ignored owners, ignored objects
bool CollisionFilter::canCollide(ObjectId a, ObjectId b) const {
  if (a == b) return false;
  const FilterEntry& ea = entries_[static_cast<std::size_t>(a)];
  const FilterEntry& eb = entries_[static_cast<std::size_t>(b)];
  if ((ea.group & eb.mask) == 0u || (eb.group & ea.mask) == 0u) return false;
  if (ea.owner >= 0 && eb.owner >= 0) {
    if (ea.owner == eb.owner) return false;
    if (!ignoredOwners_.empty() && ignoredOwners_.count(key(ea.owner, eb.owner))) return false;
  }
  return ignoredObjects_.empty() || !ignoredObjects_.count(key(a, b));
}

}  // namespace yardsim::collision
