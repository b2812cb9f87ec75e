#pragma once
// One `collision:` entry of a `mechanics:` block as written (docs/collision.md), read at the
// door with every problem reported at its node: the bodies that touch, their separate shapes,
// the ground, materials and the contact law of each material pair, ignored pairs and clearance
// watches. Resolved against the built system by collision_reader.cpp. Units: m, N, s; shapes
// in their body frame B (centred on the centre of mass).
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "collision/shape.hpp"
#include "forces/contact.hpp"
#include "scene/spec_reader.hpp"

namespace yardsim::scene::providers {

// A clearance watch as written: patterns of body or rope names (`*` matches any run of
// characters), the threshold, how far distances are computed, and where it was written.
struct WatchSpec {
  std::string name;
  std::vector<std::string> a, b;
  double below = 0.0, range = 0.0;
  int line = 0, column = 0;  // of `between`
};

// Where a name was written (1-based line and column) and its key below the entry.
struct NamePlace {
  int line = 0, column = 0;
  std::string key;
};

// A named group of bodies and ropes as written (`groups: {cranes: ["GOC201.*"], ...}`): its
// patterns and where each was written. A pair of groups under `ignore:` is never tested (the
// kernel's groups and masks); a group paired with a body or `ground` stands for its members.
struct GroupSpec {
  std::string name;
  std::vector<std::string> patterns;
  std::vector<NamePlace> places;  // per pattern
  NamePlace place;                // of the group's name
};

// Everything an entry says, read at the door; resolved against the built system later.
struct CollisionSpec {
  std::vector<std::string> bodies;
  std::map<std::string, collision::Shape> shapes;  // separate collision shapes, centred on B
  bool ground = false;
  double groundHeight = 0.0;                                // m, world z of the ground plane
  std::map<std::string, std::string> materials;             // body or "ground" => material name
  std::map<std::string, forces::ContactMaterial> laws;      // "a/b" (sorted) or "default"
  std::vector<std::pair<std::string, std::string>> ignore;  // body, ground or group names
  std::vector<GroupSpec> groups;
  std::vector<WatchSpec> watches;
  int pointsPerPair = 4;
  double ropeDiameter = 0.04;  // m, the capsules of ropes that give no diameter of their own
  // the scene-level form (`collision:` / `clearance:` at the root, the loader's `_scene`): the
  // bodies default to every body with a geometry, watch channels and events are `<watch>`, and
  // without `collision:` (only `clearance:`) there is no contact
  bool sceneLevel = false, contact = true;
  std::string keyRoot;  // what keys start with in messages: "<set>" or "collision"
  // names given under shapes, materials and ignore, where: checked against the bodies once they
  // are known (at the door for a listed set, when the system is built for a scene-level one)
  std::vector<std::pair<std::string, NamePlace>> named;
  std::vector<NamePlace> bodyPlaces;  // per listed body
  NamePlace place;                    // the entry's
};

// (node) => its 1-based line and column
NamePlace placeOf(const YAML::Node& n, std::string key);
// (name, pattern with `*`) => whether the pattern matches the whole name
bool matches(const std::string& name, const std::string& pattern);
// (spec, name) => the index of the group of that name, or -1
int groupIndex(const CollisionSpec& c, const std::string& name);
// (entry, reader, its key path) => what it says, every problem reported at its node
CollisionSpec readEntry(const YAML::Node& n, const spec::Reader& r, const std::string& key);

}  // namespace yardsim::scene::providers
