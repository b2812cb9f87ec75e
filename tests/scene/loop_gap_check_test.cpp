// A loop closure open at the start is refused at the door (issue 14: a loop frame 97 m from its
// body teleported the body at t = 0), in a scene's mechanics and in a multibody component.
#include "scene/loop_gap_check.hpp"

#include <catch2/catch.hpp>

#include "scene/scene_loader.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;

namespace {
// (frame_a of the loop on the block, m) => a block on a free joint at z = 10 tied to the world
// point (0, 0, 10)
std::string mechanicsScene(const std::string& frameA) {
  return "schema_version: 1\nmechanics:\n  bodies:\n    block: {parent: world, joint: {type: free, "
         "q0: {xyz: [0, 0, "
         "10]}}, mass: 1000, inertia: [100, 100, 100]}\n  loops:\n    tie: {body_a: block, "
         "frame_a: {xyz: " +
         frameA +
         "}, body_b: world, frame_b: {xyz: [0, 0, 10]}, constrain: point}\nintegrator: {method: "
         "rk4, dt: "
         "0.001}\nuntil: 1\n";
}
}  // namespace

TEST_CASE("a loop open at the start is refused naming the loop and its gap") {
  testing::SceneDir dir;
  CHECK(scene::loadScene(dir.write("closed.yaml", mechanicsScene("[0, 0, 0]"))).scene);
  CHECK(scene::loadScene(dir.write("nearly.yaml", mechanicsScene("[0.005, 0, 0]")))
            .scene);  // within 1 cm
  const auto r = scene::loadScene(dir.write("open.yaml", mechanicsScene("[97, 0, 0]")));
  INFO(r.diagnostics.report());
  REQUIRE(r.diagnostics.errorCount() == 1);
  CHECK(r.diagnostics.all().front().keyPath == "mechanics.loops.tie");
  // at the loop (its first value: `body_a: block`), not at `integrator:` or the mechanics block
  CHECK(r.diagnostics.all().front().where.line == 6);
  CHECK(r.diagnostics.all().front().where.column == 19);
  CHECK_THAT(r.diagnostics.all().front().message, Catch::Contains("loop 'tie' is open by 97 "));
}

TEST_CASE("a multibody component with an open loop is refused at its loops") {
  testing::SceneDir dir;
  const auto r = scene::loadScene(dir.write(
      "mb.yaml",
      "schema_version: 1\ncomponents:\n  m:\n    type: multibody\n    params:\n      dt: 0.001\n"
      "      bodies:\n        link: {parent: world, joint: {type: revolute, axis: [0, 1, 0]}, "
      "mass: 1, "
      "com: [0, 0, -0.5], inertia: [0.1, 0.1, 0.01]}\n      loops:\n        pin: {body_a: link, "
      "frame_a: "
      "{xyz: [0, 0, -1]}, body_b: world, frame_b: {xyz: [0, 0, -3]}}\nuntil: 1\n"));
  INFO(r.diagnostics.report());
  REQUIRE(r.diagnostics.errorCount() == 1);
  CHECK(r.diagnostics.all().front().keyPath == "components.m.params.loops.pin");
  CHECK(r.diagnostics.all().front().where.line == 10);  // at the loop's key
  CHECK(r.diagnostics.all().front().where.column == 9);
  CHECK_THAT(r.diagnostics.all().front().message, Catch::Contains("loop 'pin' is open by 2 "));
}
