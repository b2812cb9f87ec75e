// Names of a collision set against its shapes and ropes: patterns, groups, masks
// (collision_groups.hpp).
#include "scene/providers/collision_groups.hpp"

#include <algorithm>

namespace yardsim::scene::providers {

bool matchPattern(const std::string& pattern, const std::string& prefix,
                  const collision::BodyCollisionSpec& spec, std::vector<int>& shapes,
                  std::vector<int>& ropes) {
  const std::size_t before = shapes.size() + ropes.size();
  // (name) => the pattern matches it as written or below the fragment's path
  auto hit = [&](const std::string& name) {
    return matches(name, pattern) || matches(name, prefix + pattern);
  };
  for (std::size_t i = 0; i < spec.shapes.size(); ++i)
    if (hit(spec.shapes[i].name)) shapes.push_back(static_cast<int>(i));
  for (std::size_t i = 0; i < spec.ropes.size(); ++i)
    if (hit(spec.ropes[i].name)) ropes.push_back(static_cast<int>(i));
  return shapes.size() + ropes.size() > before;
}

void applyGroups(const CollisionSpec& c, const std::string& prefix,
                 const std::vector<std::string>& bodies,
                 const std::function<int(const std::string&)>& indexOf, const std::string& noMatch,
                 collision::BodyCollisionSpec& spec, const PlaceFail& fail) {
  if (c.groups.empty()) return;
  // (groups' patterns) => each shape's and rope's group index (-1: none), the members of each
  std::vector<int> shapeGroup(spec.shapes.size(), -1), ropeGroup(spec.ropes.size(), -1);
  std::vector<std::vector<int>> shapesOf(c.groups.size()), ropesOf(c.groups.size());
  for (std::size_t g = 0; g < c.groups.size(); ++g) {
    const GroupSpec& group = c.groups[g];
    if (std::find(bodies.begin(), bodies.end(), group.name) != bodies.end())
      fail("group '" + group.name + "' has the name of a body: give it another", group.place);
    for (std::size_t p = 0; p < group.patterns.size(); ++p) {
      std::vector<int> shapes, ropes;
      if (!matchPattern(group.patterns[p], prefix, spec, shapes, ropes))
        fail("group '" + group.name + "': '" + group.patterns[p] + "' " + noMatch, group.places[p]);
      // (members, their group per index, names) => each in this group, or fail if in another
      auto join = [&](const std::vector<int>& found, std::vector<int>& groupOf, auto nameOf) {
        for (const int i : found) {
          int& in = groupOf[static_cast<std::size_t>(i)];
          if (in >= 0 && in != static_cast<int>(g))
            fail("group '" + group.name + "': '" + nameOf(i) + "' is in group '" +
                     c.groups[static_cast<std::size_t>(in)].name +
                     "' already (a body or rope belongs to one group at most)",
                 group.places[p]);
          in = static_cast<int>(g);
        }
      };
      join(shapes, shapeGroup,
           [&](int i) { return spec.shapes[static_cast<std::size_t>(i)].name; });
      join(ropes, ropeGroup, [&](int i) { return spec.ropes[static_cast<std::size_t>(i)].name; });
    }
    for (std::size_t i = 0; i < spec.shapes.size(); ++i)
      if (shapeGroup[i] == static_cast<int>(g)) shapesOf[g].push_back(static_cast<int>(i));
    for (std::size_t i = 0; i < spec.ropes.size(); ++i)
      if (ropeGroup[i] == static_cast<int>(g)) ropesOf[g].push_back(static_cast<int>(i));
  }
  // (ignore pairs) => group-group: each one's bit off the other's mask; group-name: owner pairs
  auto bit = [](int g) { return std::uint32_t{1} << (g + 1); };
  std::vector<std::uint32_t> mask(c.groups.size(), collision::kAllGroups);
  for (const auto& [a, b] : c.ignore) {
    const int ga = groupIndex(c, a), gb = groupIndex(c, b);
    if (ga >= 0 && gb >= 0) {
      mask[static_cast<std::size_t>(ga)] &= ~bit(gb);
      mask[static_cast<std::size_t>(gb)] &= ~bit(ga);
      continue;
    }
    if (ga < 0 && gb < 0) continue;  // two bodies: the reader's own pairs
    const int g = ga >= 0 ? ga : gb;
    const std::string& other = ga >= 0 ? b : a;
    const int owner = indexOf(other);
    for (const int i : shapesOf[static_cast<std::size_t>(g)])
      spec.ignore.emplace_back(spec.shapes[static_cast<std::size_t>(i)].body, owner);
    if (other != "ground")  // ropes never touch the ground (they are in the watches only)
      for (const int r : ropesOf[static_cast<std::size_t>(g)])
        spec.ignore.emplace_back(spec.bodyCount + r, owner);
  }
  for (std::size_t i = 0; i < spec.shapes.size(); ++i)
    if (const int g = shapeGroup[i]; g >= 0) {
      spec.shapes[i].group = bit(g);
      spec.shapes[i].mask = mask[static_cast<std::size_t>(g)];
    }
  for (std::size_t i = 0; i < spec.ropes.size(); ++i)
    if (const int g = ropeGroup[i]; g >= 0) {
      spec.ropes[i].group = bit(g);
      spec.ropes[i].mask = mask[static_cast<std::size_t>(g)];
    }
}

}  // namespace yardsim::scene::providers
