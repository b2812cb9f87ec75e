// Collision groups in scenes (scene/providers/collision_groups.cpp, docs/collision.md "Groups"):
// the pairs of two groups listed under `ignore:` are never in contact and never queried by a
// watch, bodies and ropes alike, a group paired with a body or the ground stands for its members,
// and every other pair still touches and is still measured; bad group names and patterns are
// refused at their place in the file.
#include <catch2/catch.hpp>
#include <string>

#include "run/runner.hpp"
#include "scene/assembler.hpp"
#include "scene/scene_loader.hpp"
#include "support/csv_file.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;
using Catch::Matchers::Contains;

namespace {

// Three free 1 m boxes without gravity, on a contact law so soft (k = 1 N/m) that nothing moves
// in 0.02 s: crane_a at the origin, crane_b 0.9 m along x (0.1 m into crane_a), block 0.9 m along
// y (0.1 m into crane_a, and 0.1 x 0.1 m into crane_b's corner); the ground 0.1 m into every box
// when `ground` is set. A slack rope `hoist` runs on x = y = -1.5 m from the world at z = -10 m
// to a hook (a 0.1 m sphere, far from everything) at z = 10 m. Watches within a 3 m range: crane_a
// against block (-0.1 m) and hoist against block (its capsule, d = 0.04 m, to the block's edge at x
// = -0.5, y = 0.4).
std::string scene(const std::string& collision) {
  const std::string box = "mass: 1000, inertia: [100, 100, 100], geometry: {box: [1, 1, 1]}}\n";
  return R"(schema_version: 1
integrator: {method: rk4, dt: 0.01}
mechanics:
  gravity: [0, 0, 0]
  bodies:
    crane_a: {parent: world, joint: {name: a_free, type: free}, )" +
         box +
         R"(    crane_b: {parent: world, joint: {name: b_free, type: free, q0: {xyz: [0.9, 0, 0]}}, )" +
         box +
         R"(    block: {parent: world, joint: {name: c_free, type: free, q0: {xyz: [0, 0.9, 0]}}, )" +
         box + R"(    hook: {parent: world, joint: {name: hook_z, type: prismatic, axis: [0, 0, 1]},
           placement: {xyz: [-1.5, -1.5, 10]}, mass: 1, inertia: [1, 1, 1], geometry: {sphere: 0.1}}
  ropes:
    hoist: {path: [{point: [-1.5, -1.5, -10]}, {body: hook, point: [0, 0, 0]}], EA: 1.0e6,
            L0: 30, diameter: 0.04}
collision:
  contact: {default: {law: linear, k: 1.0}}
)" + collision +
         R"(clearance:
  boxes: {between: [crane_a, block], below: 0.5, range: 3}
  rope: {between: [hoist, block], below: 0.5, range: 3}
record: {interval: 0.01, channels: ["collision.points", "boxes.distance", "rope.distance"]}
)";
}

struct Reading {
  double points = 0, boxes = 0, rope = 0;
};

// (the collision keys after contact:) => the last row's contact points and watch distances
Reading simulate(const std::string& collision) {
  testing::SceneDir dir;
  auto loaded = scene::loadSceneOrThrow(dir.write("s.yaml", scene(collision)));
  auto root = scene::assemble(*loaded);
  run::runScene(*loaded, *root, {dir.path() / "out", 0.02, {}, {}});
  const testing::CsvFile csv((dir.path() / "out" / "timeseries.csv").string());
  auto last = [&](const char* name) {
    const int k = csv.column(name);
    REQUIRE(k >= 0);
    return csv.rows.back()[static_cast<std::size_t>(k)];
  };
  return {last("collision.points[-]"), last("boxes.distance[m]"), last("rope.distance[m]")};
}

// (scene file name, collision keys) => the diagnostics of loading it
std::string problems(const testing::SceneDir& dir, const std::string& name,
                     const std::string& collision) {
  return scene::loadScene(dir.write(name, scene(collision))).diagnostics.report();
}

}  // namespace

TEST_CASE("collision groups: ignored group pairs are never in contact nor queried") {
  const std::string groups =
      "  groups: {cranes: [\"crane_*\"], blocks: [block], hoists: [hoist]}\n";
  // the rope's capsule to the block's near edge at (-0.5, 0.4): |(1.0, 1.9)| - 0.02
  const double ropeToBlock = std::hypot(1.0, 1.9) - 0.02;
  // without groups: three overlapping pairs of 4 points each; both watches measure
  const Reading all = simulate("");
  CHECK(all.points == 12);
  CHECK(all.boxes == Approx(-0.1).margin(1e-9));
  CHECK(all.rope == Approx(ropeToBlock).margin(1e-6));
  // groups alone filter nothing
  const Reading none = simulate(groups);
  CHECK(none.points == 12);
  CHECK(none.boxes == Approx(-0.1).margin(1e-9));
  // cranes against blocks: crane_a-block and crane_b-block gone, crane_a-crane_b still touching;
  // the crane_a-block watch queries nothing (its range), the rope's still measures
  const Reading cb = simulate(groups + "  ignore: [[cranes, blocks]]\n");
  CHECK(cb.points == 4);
  CHECK(cb.boxes == 3.0);
  CHECK(cb.rope == Approx(ropeToBlock).margin(1e-6));
  // within one group: crane_a-crane_b gone, the two pairs with the block stay
  const Reading cc = simulate(groups + "  ignore: [[cranes, cranes]]\n");
  CHECK(cc.points == 8);
  CHECK(cc.boxes == Approx(-0.1).margin(1e-9));
  // a group and a body: the group's members with that body
  const Reading gb = simulate(groups + "  ignore: [[block, cranes]]\n");
  CHECK(gb.points == 4);
  CHECK(gb.boxes == 3.0);
  // a group of ropes against a group of bodies, and against a body: the rope watch queries nothing
  const Reading hb = simulate(groups + "  ignore: [[hoists, blocks]]\n");
  CHECK(hb.points == 12);
  CHECK(hb.rope == 3.0);
  CHECK(hb.boxes == Approx(-0.1).margin(1e-9));
  CHECK(simulate(groups + "  ignore: [[hoists, block]]\n").rope == 3.0);
}

TEST_CASE("collision groups: a group against the ground keeps its members off it") {
  // the ground at z = -0.4: 0.1 m into every box, 4 corner points each
  const std::string groups = "  ground: -0.4\n  groups: {cranes: [crane_a, crane_b]}\n";
  CHECK(simulate(groups).points == 12 + 3 * 4);
  CHECK(simulate(groups + "  ignore: [[cranes, ground]]\n").points == 12 + 4);
  CHECK(simulate(groups + "  ignore: [[cranes, ground], [cranes, cranes]]\n").points == 8 + 4);
}

TEST_CASE("collision groups: bad groups are refused at their place in the file") {
  testing::SceneDir dir;
  // line 16 is `  groups:`, line 17 `  ignore:`; a place inside a mapping or list is that of its
  // first value (the loader's resolved copy keeps no place for keys and collections)
  CHECK_THAT(problems(dir, "unknown.yaml",
                      "  groups: {cranes: [\"crane_*\"]}\n  ignore: [[cranes, blocks]]\n"),
             Contains("unknown.yaml:17:13: error: collision.ignore[0]") &&
                 Contains("'blocks' is not a body with a geometry (nor ground, nor a group)"));
  CHECK_THAT(problems(dir, "pattern.yaml", "  groups: {cranes: [crane_a, \"gantry*\"]}\n"),
             Contains("pattern.yaml:16:30: error: collision.groups.cranes[1]") &&
                 Contains("'gantry*' matches no body with a geometry, no rope"));
  CHECK_THAT(problems(dir, "twice.yaml", "  groups: {cranes: [\"crane_*\"], all: [\"*\"]}\n"),
             Contains("twice.yaml:16:39: error: collision.groups.all[0]") &&
                 Contains("'crane_a' is in group 'cranes' already"));
  CHECK_THAT(problems(dir, "body.yaml", "  groups: {block: [crane_a]}\n"),
             Contains("body.yaml:16:20: error: collision.groups.block") &&
                 Contains("group 'block' has the name of a body"));
  CHECK_THAT(problems(dir, "ground.yaml", "  groups: {ground: [crane_a]}\n"),
             Contains("ground.yaml:16:21: error: collision.groups.ground") &&
                 Contains("group 'ground' has the name of a body or of the ground"));
  CHECK_THAT(problems(dir, "list.yaml", "  groups: [crane_a]\n"),
             Contains("list.yaml:16:12: error: collision.groups: expected {group: ["));
  std::string many = "  groups: {";
  for (int i = 0; i < 32; ++i) many += (i ? ", g" : "g") + std::to_string(i) + ": [crane_a]";
  CHECK_THAT(problems(dir, "many.yaml", many + "}\n"),
             Contains("error: collision.groups.g31: at most 31 groups"));
  CHECK(problems(dir, "good.yaml",
                 "  groups: {cranes: [\"crane_*\"]}\n  ignore: [[cranes, ground]]\n")
            .find("error") == std::string::npos);
}

TEST_CASE("collision groups: a named set checks its group names at the door") {
  // the named form lists its bodies, so names are checked when the file is read
  testing::SceneDir dir;
  auto load = [&](const std::string& name, const std::string& keys) {
    return scene::loadScene(dir.write(name, R"(schema_version: 1
integrator: {method: rk4, dt: 0.01}
mechanics:
  bodies:
    a: {parent: world, joint: {name: a_free, type: free}, mass: 1, inertia: [1, 1, 1],
        geometry: {box: [1, 1, 1]}}
  collision:
    s:
      bodies: [a]
      contact: {default: {law: linear, k: 1.0}}
)" + keys))
        .diagnostics.report();
  };
  CHECK_THAT(load("unknown.yaml", "      groups: {g: [a]}\n      ignore: [[g, h]]\n"),
             Contains("unknown.yaml:12:17: error: mechanics.collision.s.ignore[0]") &&
                 Contains("'h' is not one of bodies (or ground, or a group)"));
  CHECK_THAT(load("body.yaml", "      groups: {a: [a]}\n"),
             Contains("body.yaml:11:20: error: mechanics.collision.s.groups.a") &&
                 Contains("group 'a' has the name of a body"));
  CHECK(load("good.yaml", "      groups: {g: [a]}\n      ignore: [[g, g], [g, ground]]\n")
            .find("error") == std::string::npos);
}
