// The door checks of a system's events: an unknown element or kind in an actor's stop_on list is
// refused at the list (file:line:col) with its key path and the valid names; full names, trailing
// parts and every kind of event a system raises (a watch's, a rope's, a drive's) are accepted; a
// clearance watch already touching at the start is warned about (its events count crossings only).
#include <catch2/catch.hpp>

#include "scene/scene_loader.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;
using Catch::Matchers::Contains;

namespace {

// (stop_on list, the cart's q0) => a scene whose actor `haul` stops on it: a rope (diameter
// 0.04 m, on x = 0) beside a cart whose face is at x = q0 - 1, watched
std::string withStopOn(const std::string& stopOn, const std::string& q0 = "3") {
  return R"(schema_version: 1
integrator: {method: rk4, dt: 0.01}
components:
  haul: {type: wire_actor, params: {rope: hoist, payout: -5, speed: 0.1,
                                    stop_on: )" +
         stopOn + R"(}}
mechanics:
  gravity: [0, 0, 0]
  bodies:
    hook:
      parent: world
      joint: {name: hook_z, type: prismatic, axis: [0, 0, 1]}
      mass: 100
      inertia: [1, 1, 1]
    cart:
      parent: hook
      joint: {name: cart_x, type: prismatic, axis: [1, 0, 0], q0: )" +
         q0 + R"(}
      mass: 1000
      inertia: [100, 100, 100]
      geometry: {box: [2, 2, 2]}
  ropes:
    hoist: {path: [{point: [0, 0, 10]}, {body: hook, point: [0, 0, 0]}], EA: 1.0e6, L0: 10.5}
clearance:
  rope_cart: {between: [hoist, cart], below: 1.0, range: 3}
)";
}

}  // namespace

TEST_CASE("stop_on: an unknown element or kind is refused at the door with the valid names") {
  testing::SceneDir dir;
  const auto kind = scene::loadScene(dir.write("kind.yaml", withStopOn("[rope_cart.touchd]")));
  REQUIRE(kind.diagnostics.hasErrors());
  const std::string k = kind.diagnostics.report();
  CHECK_THAT(k, Contains("kind.yaml:5:46") && Contains("components.haul.params.stop_on") &&
                    Contains("no event 'rope_cart.touchd'"));
  CHECK_THAT(k, Contains("rope_cart.touched") && Contains("rope_cart.clearance_below") &&
                    Contains("hoist.slack") && Contains("cart_x.reached"));
  const auto element =
      scene::loadScene(dir.write("element.yaml", withStopOn("[rope_block.touched]")));
  CHECK_THAT(element.diagnostics.report(),
             Contains("element.yaml:5:46") && Contains("no event 'rope_block.touched'"));
  // a second name is checked too
  const auto second =
      scene::loadScene(dir.write("second.yaml", withStopOn("[rope_cart.touched, winch.done]")));
  CHECK_THAT(second.diagnostics.report(), Contains("no event 'winch.done'"));
}

TEST_CASE("stop_on: full names and trailing parts of the system's events are accepted") {
  testing::SceneDir dir;
  for (const std::string ok : {"[rope_cart.touched]", "[touched]", "[rope_cart.clearance_below]",
                               "[hoist.slack, hoist.over_mbl]", "[cart_x.reached]"}) {
    INFO(ok);
    const auto r = scene::loadScene(dir.write("ok.yaml", withStopOn(ok)));
    CHECK_FALSE(r.diagnostics.hasErrors());
    if (r.diagnostics.hasErrors()) WARN(r.diagnostics.report());
  }
}

TEST_CASE("events at start: a watch that touches from the start is warned about") {
  testing::SceneDir dir;
  // the cart's face at x = 0.01: the rope's capsule (radius 0.02) 0.01 m into it
  const auto touching = scene::loadScene(dir.write("t.yaml", withStopOn("[touched]", "1.01")));
  REQUIRE_FALSE(touching.diagnostics.hasErrors());
  const std::string w = touching.diagnostics.report();
  CHECK_THAT(w, Contains("warning: clearance.rope_cart:") &&
                    Contains("'rope_cart' is past its 'touched' event at the start (value -0.01") &&
                    Contains("'clearance_below'") && Contains("hoist at (0.020,"));
  // 0.5 m away: below the 1 m threshold, not touching
  const auto near = scene::loadScene(dir.write("n.yaml", withStopOn("[touched]", "1.5")));
  CHECK_THAT(near.diagnostics.report(), Contains("'clearance_below'"));
  CHECK_THAT(near.diagnostics.report(), !Contains("'touched'"));
  // 2 m away: nothing
  const auto apart = scene::loadScene(dir.write("a.yaml", withStopOn("[touched]")));
  CHECK_THAT(apart.diagnostics.report(), !Contains("at the start"));
}
