// "A scene without collision builds no FCL object at all" (issue 15, docs/collision.md): the
// process-wide FCL counts (collision::fclCounts) do not move while a scene with bodies, their
// geometry and a rope, but no `collision:` or `clearance:`, is loaded, built and run; the same
// scene with a collision set makes its worlds and objects, and they are all gone with the scene.
// FCL itself (the module libyardsim_fcl.so and libfcl) is mapped only once a scene has collision.
#include <catch2/catch.hpp>
#include <string>

#include "collision/collision_world.hpp"
#include "run/runner.hpp"
#include "scene/assembler.hpp"
#include "scene/scene_loader.hpp"
#include "support/loaded_objects.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;

namespace {

// a 1 t box with a geometry hanging from a rope over a box on the world; `extra` at the root
std::string sceneText(const std::string& extra) {
  return R"(schema_version: 1
integrator: {method: rk4, dt: 0.01}
mechanics:
  bodies:
    base: {parent: world, joint: {name: base_fix, type: fixed}, mass: 1000,
           inertia: [100, 100, 100], geometry: {box: [4, 4, 1]}}
    box: {parent: world, joint: {name: box_free, type: free, q0: {xyz: [0, 0, 3]}}, mass: 1000,
          inertia: [166.7, 166.7, 166.7], geometry: {box: [1, 1, 1]}}
  ropes:
    hoist: {path: [{point: [0, 0, 10]}, {body: box, point: [0, 0, 0.5]}], EA: 1.0e7, L0: 6.5}
)" + extra +
         R"(record: {interval: 0.1, channels: ["box.*"]}
)";
}

// (scene text) => the FCL counts while the built scene lives (after its run), and after it is gone
std::pair<collision::FclCounts, collision::FclCounts> runCounted(const std::string& text) {
  testing::SceneDir dir;
  collision::FclCounts during;
  {
    auto loaded = scene::loadSceneOrThrow(dir.write("s.yaml", text));
    auto root = scene::assemble(*loaded);
    run::runScene(*loaded, *root, {dir.path() / "out", 0.5, {}, {}});
    during = collision::fclCounts();
  }
  return {during, collision::fclCounts()};
}

}  // namespace

TEST_CASE("collision scene: a scene without collision builds no FCL object at all") {
  const collision::FclCounts before = collision::fclCounts();
  const auto [during, after] = runCounted(sceneText(""));
  CHECK(during.worldsMade == before.worldsMade);
  CHECK(during.objectsMade == before.objectsMade);
  CHECK(after.worldsMade == before.worldsMade);
  CHECK(after.objectsMade == before.objectsMade);
  // (each test case runs in its own process under ctest) => FCL never loaded
  CHECK_FALSE(testing::loaded("libfcl"));
  CHECK_FALSE(testing::loaded("libyardsim_fcl"));
}

TEST_CASE("collision scene: a scene with collision builds FCL objects and frees them") {
  // the check above would see a scene with collision: its two worlds (contact and clearance),
  // their probes and the two boxes in the contact world at least
  const collision::FclCounts before = collision::fclCounts();
  const auto [during, after] =
      runCounted(sceneText("collision: {ground: 0, contact: {default: {law: linear, k: 1.0e8}}}\n"
                           "clearance: {w: {between: [hoist, base], below: 0.5}}\n"));
  CHECK(during.worldsAlive >= before.worldsAlive + 2);
  CHECK(during.objectsAlive >= before.objectsAlive + 2 + 2);
  CHECK(during.objectsMade > before.objectsMade);
  CHECK(after.worldsAlive == before.worldsAlive);
  CHECK(after.objectsAlive == before.objectsAlive);
  CHECK(testing::loaded("libyardsim_fcl"));
  CHECK(testing::loaded("libfcl"));
}
