// The `collision:` key of a `mechanics:` block (docs/collision.md), and the scene-level
// `collision:` / `clearance:` that the loader turns into one such entry named `collision` (every
// body with a geometry unless `bodies:` lists them; watch channels `<watch>.distance`, events on
// element `<watch>`): one entry is one collision set of a mechanical system — the bodies that touch
// (each body's `geometry` is its collision shape unless `shapes:` gives another), an optional
// ground, materials and the contact law of each material pair (forces/contact.hpp, evaluated at
// every integrator stage), ignored pairs (bodies, ground or groups: collision_groups.hpp), and
// clearance watches between bodies and ropes
// (collision/body_collision.hpp). Channels: <name>.points, <name>.normal_force, <name>.<body>.fz
// per body, <name>.<watch>.distance per watch, and <name>.energy / <name>.power like every
// provider.
#include <algorithm>
#include <memory>

#include "collision/collision_set.hpp"
#include "dynamics/kinematics.hpp"
#include "forces/geometry/triangle_mesh.hpp"
#include "scene/provider_readers.hpp"
#include "scene/providers/collision_entry.hpp"
#include "scene/providers/collision_groups.hpp"

namespace yardsim::scene::providers {

namespace {

using mechanics::BuiltMechanics;
using mechanics::MechanicsSpec;

// (a body's geometry) => its collision shape at X_BS; false when it has none (Auto)
bool shapeOf(const MechanicsSpec::Visual& v, const dynamics::SpatialInertia& in,
             collision::Shape& shape, dynamics::Transform& X_BS) {
  using S = MechanicsSpec::Visual::Shape;
  X_BS = v.posed ? v.X_BG : dynamics::Transform{dynamics::Matrix3::Identity(), in.com};
  switch (v.shape) {
    case S::Box:
      shape = collision::Shape::box(v.size);
      return true;
    case S::Cylinder:
      shape = collision::Shape::cylinder(v.size[0], v.size[1]);
      return true;
    case S::Sphere:
      shape = collision::Shape::sphere(v.size[0]);
      return true;
    case S::Mesh:
      forces::checkClosedMesh(*v.mesh);  // contact depths need a closed surface
      shape = collision::Shape::triangleMesh(v.mesh);
      return true;
    default:
      return false;
  }
}

// (what the entry says, its provider name, the built system, attachments = its bodies) => the
// collision set's contact provider with its channels; ProviderPlaceError at the entry's node for
// a name that matches nothing, a body without a usable shape or a shape the kernel refuses
std::unique_ptr<forces::ForceProvider> build(const CollisionSpec& c, const std::string& name,
                                             const BuiltMechanics& mech,
                                             const std::vector<forces::Attachment>& at) {
  const dynamics::Model& model = mech.model;
  const std::string prefix = name.substr(0, name.rfind('.') + 1);  // the fragment's path
  // (message, where and which key) => the problem at its place in the file
  auto fail = [&](const std::string& msg, int line, int column, const std::string& key) {
    throw scene::ProviderPlaceError("collision '" + name + "': " + msg, name, line, column,
                                    c.sceneLevel && key.starts_with(c.keyRoot + ".clearance.")
                                        ? key.substr(c.keyRoot.size() + 1)
                                        : key,
                                    c.sceneLevel);
  };
  // (the bodies: as listed, or every body with a geometry by its full name) => per attachment
  std::vector<std::string> bodies = c.bodies;
  if (bodies.empty())
    for (const auto& a : at) bodies.push_back(model.names[static_cast<std::size_t>(a.body)]);
  for (const auto& [b, where] : c.named)  // (names under shapes, materials, ignore) => bodies
    if (std::find(bodies.begin(), bodies.end(), b) == bodies.end())
      fail("'" + b + "' is not a body with a geometry" +
               (where.key.find(".ignore[") != std::string::npos && !c.groups.empty()
                    ? " (nor ground, nor a group)"
                    : ""),
           where.line, where.column, where.key);
  collision::BodyCollisionSpec spec;
  spec.bodyCount = model.nbodies;
  spec.maxPointsPerPair = c.pointsPerPair;
  spec.contact = c.contact;
  // (materials) => names, the pair table from the laws
  std::vector<std::string> materialNames{"default"};
  auto materialOf = [&](const std::string& body) {
    const auto it = c.materials.find(body);
    const std::string m = it == c.materials.end() ? "default" : it->second;
    const auto found = std::find(materialNames.begin(), materialNames.end(), m);
    if (found != materialNames.end()) return static_cast<int>(found - materialNames.begin());
    materialNames.push_back(m);
    return static_cast<int>(materialNames.size() - 1);
  };
  std::vector<std::pair<std::string, int>> reactions;  // (name as written, body index)
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const int body = at.at(i).body;
    const auto& visual = mech.visuals.at(static_cast<std::size_t>(body));
    collision::BodyShape s{
        body, model.names[static_cast<std::size_t>(body)], {}, {}, materialOf(bodies[i])};
    if (const auto it = c.shapes.find(bodies[i]); it != c.shapes.end()) {
      s.shape = it->second;
      s.X_BS = {dynamics::Matrix3::Identity(), model.inertias[static_cast<std::size_t>(body)].com};
    } else {
      try {
        if (!shapeOf(visual, model.inertias[static_cast<std::size_t>(body)], s.shape, s.X_BS))
          fail("body '" + bodies[i] + "' has no geometry: give it one, or a shape under shapes:",
               c.bodyPlaces.at(i).line, c.bodyPlaces.at(i).column, c.bodyPlaces.at(i).key);
      } catch (const forces::MeshError& e) {
        throw std::invalid_argument("collision '" + name + "': body '" + bodies[i] +
                                    "': its mesh cannot be used for contact: " + e.what());
      }
    }
    spec.shapes.push_back(std::move(s));
    reactions.emplace_back(bodies[i], body);
  }
  spec.ground = c.ground;
  spec.groundHeight = c.groundHeight;
  spec.groundMaterial = materialOf("ground");
  const int nm = static_cast<int>(materialNames.size());
  std::vector<forces::ContactMaterial> laws{c.laws.at("default")};
  spec.materialCount = nm;
  spec.pairLaw.assign(static_cast<std::size_t>(nm * nm), 0);
  for (int a = 0; a < nm; ++a)
    for (int b = 0; b < nm; ++b) {
      const std::string& x = materialNames[static_cast<std::size_t>(std::min(a, b))];
      const std::string& y = materialNames[static_cast<std::size_t>(std::max(a, b))];
      const auto it = c.laws.find(std::min(x, y) + "/" + std::max(x, y));
      if (it == c.laws.end()) continue;
      laws.push_back(it->second);
      spec.pairLaw[static_cast<std::size_t>(a * nm + b)] = static_cast<int>(laws.size() - 1);
    }
  // (joints, the scene's ignore list) => pairs never tested: a body and its parent unless free
  for (int i = 1; i < model.nbodies; ++i)
    if (model.jointNv[static_cast<std::size_t>(i)] != 6)
      spec.ignore.emplace_back(i, model.parent[static_cast<std::size_t>(i)]);
  auto indexOf = [&](const std::string& n) {
    if (n == "ground") return 0;
    const auto it = std::find(bodies.begin(), bodies.end(), n);
    return at.at(static_cast<std::size_t>(it - bodies.begin())).body;
  };
  for (const auto& [a, b] : c.ignore)  // (two bodies or ground) => the pair; groups: below
    if (groupIndex(c, a) < 0 && groupIndex(c, b) < 0)
      spec.ignore.emplace_back(indexOf(a), indexOf(b));
  // (ropes, and each branch of an equalizer from its sheave) => capsules with their own diameter
  // (the set's rope_diameter when they give none); only those a watch names are built
  auto bodyOf = [&](const std::string& b) { return b == "world" ? 0 : model.bodyIndex(b); };
  for (const auto& r : mech.ropes) {
    collision::RopeShape rope{
        r.name, {}, r.material.diameter > 0 ? r.material.diameter : c.ropeDiameter};
    for (const auto& [body, p] : r.path) rope.path.emplace_back(bodyOf(body), p);
    spec.ropes.push_back(std::move(rope));
  }
  for (const auto& e : mech.equalizers)
    for (const auto& branch : e.branches) {
      collision::RopeShape rope{
          e.name, {}, e.material.diameter > 0 ? e.material.diameter : c.ropeDiameter};
      rope.path.emplace_back(bodyOf(e.sheave.first), e.sheave.second);
      for (const auto& [body, p] : branch) rope.path.emplace_back(bodyOf(body), p);
      spec.ropes.push_back(std::move(rope));
    }
  const std::string noMatch =
      std::string("matches no body") +
      (c.sceneLevel && c.bodies.empty() ? " with a geometry" : " of bodies:") +
      ", no rope and no equalizer";
  // (groups) => group bits and masks of the shapes and ropes, a group's pairs with a body
  applyGroups(
      c, prefix, bodies, indexOf, noMatch, spec,
      [&](const std::string& msg, const NamePlace& p) { fail(msg, p.line, p.column, p.key); });
  for (const WatchSpec& w : c.watches) {
    collision::ClearanceSpec cs{w.name, {}, {}, {}, {}, w.below, w.range};
    auto side = [&](const std::vector<std::string>& patterns, std::vector<int>& shapes,
                    std::vector<int>& ropes) {
      for (const std::string& p : patterns)
        if (!matchPattern(p, prefix, spec, shapes, ropes))
          fail("clearance '" + w.name + "': '" + p + "' " + noMatch, w.line, w.column,
               c.keyRoot + ".clearance." + w.name + ".between");
    };
    side(w.a, cs.shapesA, cs.ropesA);
    side(w.b, cs.shapesB, cs.ropesB);
    spec.watches.push_back(std::move(cs));
  }
  dynamics::Data kin(model);
  dynamics::forwardKinematics(model, kin, mech.q0, mech.v0);
  std::shared_ptr<collision::BodyCollision> world;
  try {
    world = std::make_shared<collision::BodyCollision>(std::move(spec), kin);
  } catch (const collision::CollisionError& e) {
    fail(e.what(), c.place.line, c.place.column, c.place.key);
  }
  collision::CollisionSet::Options options;
  options.contact = c.contact;
  options.watchesAtTop = c.sceneLevel;
  if (!c.contact) reactions.clear();
  return std::make_unique<collision::CollisionSet>(name, std::move(world), std::move(laws),
                                                   reactions, options);
}

}  // namespace

YARDSIM_REGISTER_PROVIDER(
    collisionSets,
    ProviderReader{
        .key = "collision",
        .summary =
            "name: {bodies: [a, b], ground: z, shapes, materials, contact: {default: {law, k, "
            "n, c | restitution, mu}}, groups: {g: [a, b*]}, ignore: [[a | g, b | g]], "
            "clearance: {w: {between: [a, b], below: m}}}",
        .read = [](const std::string&, const YAML::Node& n, const spec::Reader& r,
                   const std::string& key) {
          MechanicsSpec::ProviderSpec out;
          const CollisionSpec c = readEntry(n, r, key);
          for (const auto& b : c.bodies) out.attachments.push_back({b, dynamics::Vector3::Zero()});
          out.everyBodyWithGeometry = c.sceneLevel && c.bodies.empty();
          out.buildFromSystem = [c](const std::string& name, const BuiltMechanics& mech,
                                    const std::vector<forces::Attachment>& at) {
            return build(c, name, mech, at);
          };
          return out;
        }});

}  // namespace yardsim::scene::providers
