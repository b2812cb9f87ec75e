#pragma once
// The names of a collision set resolved against its built shapes and ropes
// (collision_reader.cpp): the patterns of clearance watches and of groups (`*` any run of
// characters, a name as written or below the fragment's path), and the groups turned into the
// kernel's group bits and masks (collision/collision_filter.hpp): group k holds bit k + 1,
// what no group holds bit 0; a pair of groups under `ignore:` clears each one's bit from the
// other's mask, so none of their pairs is ever tested (contact or watch); a group paired with a
// body or `ground` stands for its members (owner pairs).
#include <functional>
#include <string>
#include <vector>

#include "collision/body_collision.hpp"
#include "scene/providers/collision_entry.hpp"

namespace yardsim::scene::providers {

// (message, where) => the problem at its place in the file (throws)
using PlaceFail = std::function<void(const std::string&, const NamePlace&)>;

// (pattern, the fragment's path with its trailing dot, spec) => the indices of the shapes and
// ropes whose names it matches, appended; whether it matched any
bool matchPattern(const std::string& pattern, const std::string& prefix,
                  const collision::BodyCollisionSpec& spec, std::vector<int>& shapes,
                  std::vector<int>& ropes);

// (entry, prefix, the set's body names, body index of a body name or "ground", spec with its
// shapes and ropes, what "matches nothing" says) => group and mask of every shape and rope, and the
// pairs of a group and a body or ground in spec.ignore (a rope r as owner spec.bodyCount + r);
// through fail: a group named like a body, a pattern that matches nothing, an object in two groups
void applyGroups(const CollisionSpec& c, const std::string& prefix,
                 const std::vector<std::string>& bodies,
                 const std::function<int(const std::string&)>& indexOf, const std::string& noMatch,
                 collision::BodyCollisionSpec& spec, const PlaceFail& fail);

}  // namespace yardsim::scene::providers
