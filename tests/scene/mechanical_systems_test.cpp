// Mechanical composition: fragments of mechanics from several coupled models (one crane file
// included twice, a block at the scene root, an unrelated pendulum) are merged, placed, and
// grouped into mechanically connected systems; actors inside the crane file act on their own
// crane's rope by its local name.
#include "scene/mechanical_systems.hpp"

#include <catch2/catch.hpp>
#include <cmath>

#include "devs/simulator.hpp"
#include "scene/assembler.hpp"
#include "models/channels.hpp"
#include "scene/scene_loader.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;

namespace {

const char* kCrane = R"(schema_version: 1
params: {hook: [0, 0, 1]}
components:
  hoist_actor: {type: wire_actor, params: {rope: hoist, payout: -0.5, speed: 0.1, start_at: 1.0}}
mechanics:
  bodies:
    trolley:
      parent: world
      joint: {type: fixed}
      placement: {xyz: [0, 0, 20]}
      mass: 1000
      inertia: [100, 100, 100]
  ropes:
    hoist:
      path: [{body: trolley, point: [0, 0, 0]}, {body: block, point: $hook}]
      EA: 1.0e8
      L0: 10.0
      damping: 2.0e5
)";

// the block's weight shared by two vertical ropes: T = m g / 2, stretch T L0 / EA
const double kM = 20000.0, kG = 9.81, kT = kM * kG / 2.0, kZ = 20.0 - 10.0 * (1.0 + kT / 1.0e8) - 1.0;

std::string sceneYaml() {
  return R"(schema_version: 1
integrator: {method: rk4, dt: 0.002}
components:
  crane1: {include: crane.yaml, params: {hook: [-5, 0, 1]}, placement: {xyz: [-5, 0, 0]}}
  crane2: {include: crane.yaml, params: {hook: [5, 0, 1]}, placement: {xyz: [5, 0, 0]}}
  lab:
    coupled:
      mechanics:
        bodies:
          bob: {parent: world, joint: {type: revolute, axis: [0, 1, 0]}, mass: 1, com: [0, 0, -1], inertia: [0.01, 0.01, 0.01]}
mechanics:
  bodies:
    block:
      parent: world
      joint: {type: free, q0: {xyz: [0, 0, )" + std::to_string(kZ) + R"(]}}
      mass: 20000
      inertia: [5.0e4, 5.0e4, 5.0e4]
)";
}

double channel(const std::vector<models::Channel>& all, const std::string& name) {
  for (const auto& c : all)
    if (c.name == name) return c.read();
  FAIL("no channel " << name);
  return 0.0;
}

}  // namespace

TEST_CASE("fragments of mechanics merge into connected systems, placed and named by path") {
  testing::SceneDir dir;
  dir.write("crane.yaml", kCrane);
  const auto r = scene::loadScene(dir.write("s.yaml", sceneYaml()));
  INFO(r.diagnostics.report());
  REQUIRE(r.scene);
  const auto& systems = r.scene->systems;
  REQUIRE(systems.size() == 2);  // two cranes holding one block are one system; the pendulum another
  std::vector<std::string> first, second;
  for (const auto& b : systems[0]->spec.bodies) first.push_back(b.name);
  for (const auto& b : systems[1]->spec.bodies) second.push_back(b.name);
  std::sort(first.begin(), first.end());
  CHECK(first == std::vector<std::string>{"block", "crane1.trolley", "crane2.trolley"});
  CHECK(second == std::vector<std::string>{"lab.bob"});
  CHECK(systems[0]->name == "mechanics1");
  REQUIRE(systems[0]->spec.ropes.size() == 2);
  CHECK(systems[0]->spec.ropes[0].name == "crane1.hoist");

  auto root = scene::assemble(*r.scene);
  const auto channels = models::collectChannels(*root);
  CHECK(channel(channels, "crane2.trolley.x") == Approx(5.0));  // its file's placement applied
  CHECK(channel(channels, "crane1.trolley.z") == Approx(20.0));
  devs::Simulator sim(*root);
  sim.runUntil(0.9);
  CHECK(channel(channels, "crane1.hoist.tension") == Approx(kT).epsilon(1e-4));
  CHECK(channel(channels, "crane2.hoist.tension") == Approx(kT).epsilon(1e-4));
  // each crane's actor hoists its own rope by 0.5 m (from t = 1 s for 5 s): the block rises 0.5 m
  sim.runUntil(12.0);
  CHECK(channel(channels, "block.z") - kZ == Approx(0.5).margin(1e-3));
}

TEST_CASE("a fragment naming a body that exists nowhere is refused with a suggestion") {
  testing::SceneDir dir;
  dir.write("crane.yaml", std::string(kCrane).replace(std::string(kCrane).find("body: block"), 11, "body: blok"));
  const auto r = scene::loadScene(dir.write("s.yaml", sceneYaml()));
  INFO(r.diagnostics.report());
  REQUIRE_FALSE(r.scene);
  CHECK_THAT(r.diagnostics.report(), Catch::Contains("unknown body 'blok'") &&
                                         Catch::Contains("did you mean 'block'?"));
  // issue 14: located at the offending value in crane.yaml, not at the first key of mechanics:
  const std::string crane =
      std::string(kCrane).replace(std::string(kCrane).find("body: block"), 11, "body: blok");
  const auto at = crane.find("blok");
  const auto lineStart = crane.rfind('\n', at) + 1;
  const auto& d = r.diagnostics.all().front();
  CHECK(d.where.file.ends_with("crane.yaml"));
  CHECK(d.where.line == 1 + static_cast<int>(std::count(
                                crane.begin(), crane.begin() + static_cast<long>(at), '\n')));
  CHECK(d.where.column == static_cast<int>(at - lineStart) + 1);
  CHECK_THAT(d.keyPath, Catch::Contains("mechanics.ropes.hoist"));
}

TEST_CASE("a scene with mechanics needs an integrator step") {
  testing::SceneDir dir;
  dir.write("crane.yaml", kCrane);
  std::string text = sceneYaml();
  text.erase(text.find("integrator:"), text.find('\n', text.find("integrator:")) - text.find("integrator:") + 1);
  const auto r = scene::loadScene(dir.write("s.yaml", text));
  CHECK_THAT(r.diagnostics.report(), Catch::Contains("integrator: {method: rk4, dt: 0.01}"));
}

TEST_CASE("equilibrium: true at the root starts the block hanging still on its stretched ropes") {
  testing::SceneDir dir;
  dir.write("crane.yaml", kCrane);
  std::string text = sceneYaml();
  // start the block 0.3 m too high, where the ropes are slack, and ask for equilibrium
  const std::string z = std::to_string(kZ);
  text.replace(text.find(z), z.size(), std::to_string(kZ + 0.3));
  text.replace(text.find("mechanics:\n  bodies:\n    block:"), 11, "mechanics:\n  equilibrium: true\n");
  const auto r = scene::loadScene(dir.write("s.yaml", text));
  INFO(r.diagnostics.report());
  REQUIRE(r.scene);
  auto root = scene::assemble(*r.scene);
  const auto channels = models::collectChannels(*root);
  CHECK(channel(channels, "block.z") == Approx(kZ).margin(1e-9));
  CHECK(channel(channels, "crane1.hoist.tension") == Approx(kT).epsilon(1e-9));
  devs::Simulator sim(*root);
  sim.runUntil(0.9);  // before the hoists start: nothing moves
  CHECK(channel(channels, "block.z") == Approx(kZ).margin(1e-9));
}

TEST_CASE("system-wide mechanics settings are refused outside the scene root") {
  testing::SceneDir dir;
  std::string crane = kCrane;
  crane.replace(crane.find("mechanics:\n"), 11, "mechanics:\n  equilibrium: true\n");
  dir.write("crane.yaml", crane);
  const auto r = scene::loadScene(dir.write("s.yaml", sceneYaml()));
  REQUIRE_FALSE(r.scene);
  CHECK_THAT(r.diagnostics.report(), Catch::Contains("crane.yaml:6:") &&
                                         Catch::Contains("mechanics.equilibrium") &&
                                         Catch::Contains("give it in the scene root's mechanics"));
}

TEST_CASE("an action list: start rules couple the named actors, unknown names are refused") {
  testing::SceneDir dir;
  dir.write("crane.yaml", kCrane);
  std::string text = sceneYaml();
  // a third actor at the root starts when both cranes' hoists have finished (no couplings)
  text.replace(text.find("  lab:"), 0,
               "  lower: {type: wire_actor, params: {rope: crane1.hoist, payout: 0.2, speed: 0.1, "
               "after_all: [crane1.hoist_actor, crane2.hoist_actor]}}\n");
  const auto r = scene::loadScene(dir.write("s.yaml", text));
  INFO(r.diagnostics.report());
  REQUIRE(r.scene);
  auto root = scene::assemble(*r.scene);
  const auto channels = models::collectChannels(*root);
  devs::Simulator sim(*root);
  sim.runUntil(5.9);  // the hoists run from 1 s to 6 s: the lowering has not started
  CHECK(channel(channels, "crane1.hoist.unstretched_length") == Approx(10.0 - 0.49).margin(1e-9));
  sim.runUntil(8.5);  // started at 6 s, paying out 0.2 m at 0.1 m/s until 8 s
  CHECK(channel(channels, "crane1.hoist.unstretched_length") == Approx(10.0 - 0.5 + 0.2).margin(1e-9));
  CHECK(channel(channels, "crane2.hoist.unstretched_length") == Approx(10.0 - 0.5).margin(1e-9));

  text.replace(text.find("crane2.hoist_actor]"), 19, "crane2.hoist_actr]");
  const auto bad = scene::loadScene(dir.write("s.yaml", text));
  REQUIRE_FALSE(bad.scene);
  CHECK_THAT(bad.diagnostics.report(), Catch::Contains("components.lower.params.after_all") &&
                                           Catch::Contains("no actor 'crane2.hoist_actr'") &&
                                           Catch::Contains("did you mean 'crane2.hoist_actor'?"));
}

TEST_CASE("watches and loads in fragments resolve like other names, unknown elements are refused") {
  testing::SceneDir dir;
  std::string crane = kCrane;
  crane += R"(  watch:
    taut: {channel: hoist.tension, above: 1.0e5}
  loads:
    gust: {body: block, series: [[0, 0, 0, 0, 0, 0, 0]]}
)";
  dir.write("crane.yaml", crane);
  const auto r = scene::loadScene(dir.write("s.yaml", sceneYaml()));
  INFO(r.diagnostics.report());
  REQUIRE(r.scene);
  const auto& spec = r.scene->systems[0]->spec;
  REQUIRE(spec.watches.size() == 2);  // one per crane instance
  CHECK(spec.watches[0].name == "crane1.taut");
  CHECK(spec.watches[0].element == "crane1.hoist");
  REQUIRE(spec.loads.size() == 2);
  CHECK(spec.loads[1].name == "crane2.gust");
  CHECK(spec.loads[1].body == "block");

  crane.replace(crane.find("hoist.tension"), 13, "hoits.tension");
  dir.write("crane.yaml", crane);
  const auto bad = scene::loadScene(dir.write("s.yaml", sceneYaml()));
  REQUIRE_FALSE(bad.scene);
  CHECK_THAT(bad.diagnostics.report(), Catch::Contains("watch.taut") && Catch::Contains("unknown element 'hoits'") &&
                                           Catch::Contains("did you mean 'hoist'?"));
  // issue 14: at the channel's value in crane.yaml, not at the first key of its mechanics:
  const auto& d = bad.diagnostics.all().front();
  const auto at = crane.find("hoits.tension");
  CHECK(d.where.file.ends_with("crane.yaml"));
  CHECK(d.where.line == 1 + static_cast<int>(std::count(
                                crane.begin(), crane.begin() + static_cast<long>(at), '\n')));
  CHECK(d.where.column == static_cast<int>(at - crane.rfind('\n', at)));
  CHECK_THAT(d.keyPath, Catch::EndsWith("mechanics.watch.taut.channel"));
}

TEST_CASE("a placement with roll, pitch and yaw, nested twice, puts a body where the hand computation does") {
  // post at p = (1, 2, 3) in its file; that file placed at (10, 0, 0) with rpy (30, 20, 50) deg
  // inside a file placed at (0, 5, 0) with rpy (-15, 40, 90) deg: p_W = p1 + R1 (p2 + R2 p),
  // R = Rz(yaw) Ry(pitch) Rx(roll) written out here with elementary rotations
  testing::SceneDir dir;
  dir.write("post.yaml", R"(schema_version: 1
mechanics:
  bodies:
    post: {parent: world, joint: {type: fixed}, placement: {xyz: [1, 2, 3]}, mass: 1, inertia: [1, 1, 1]}
)");
  dir.write("yard.yaml", R"(schema_version: 1
components:
  inner: {include: post.yaml, placement: {xyz: [10, 0, 0], rpy_deg: [30, 20, 50]}}
)");
  const auto r = scene::loadScene(dir.write("s.yaml", R"(schema_version: 1
integrator: {method: rk4, dt: 0.01}
components:
  outer: {include: yard.yaml, placement: {xyz: [0, 5, 0], rpy_deg: [-15, 40, 90]}}
)"));
  INFO(r.diagnostics.report());
  REQUIRE(r.scene);
  auto rot = [](double rollDeg, double pitchDeg, double yawDeg) {
    const double a = rollDeg * M_PI / 180, b = pitchDeg * M_PI / 180, c = yawDeg * M_PI / 180;
    Eigen::Matrix3d Rx, Ry, Rz;
    Rx << 1, 0, 0, 0, std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a);
    Ry << std::cos(b), 0, std::sin(b), 0, 1, 0, -std::sin(b), 0, std::cos(b);
    Rz << std::cos(c), -std::sin(c), 0, std::sin(c), std::cos(c), 0, 0, 0, 1;
    return Eigen::Matrix3d(Rz * Ry * Rx);
  };
  const Eigen::Matrix3d R1 = rot(-15, 40, 90), R2 = rot(30, 20, 50);
  const Eigen::Vector3d expected = Eigen::Vector3d(0, 5, 0) + R1 * (Eigen::Vector3d(10, 0, 0) + R2 * Eigen::Vector3d(1, 2, 3));
  const Eigen::Matrix3d R = R1 * R2;  // the post's orientation in the world
  auto root = scene::assemble(*r.scene);
  const auto channels = models::collectChannels(*root);
  CHECK(channel(channels, "outer.inner.post.x") == Approx(expected.x()).margin(1e-12));
  CHECK(channel(channels, "outer.inner.post.y") == Approx(expected.y()).margin(1e-12));
  CHECK(channel(channels, "outer.inner.post.z") == Approx(expected.z()).margin(1e-12));
  // (roll, pitch, yaw of R) => the same rotation rebuilt
  const Eigen::Matrix3d back = rot(channel(channels, "outer.inner.post.roll") * 180 / M_PI,
                                   channel(channels, "outer.inner.post.pitch") * 180 / M_PI,
                                   channel(channels, "outer.inner.post.yaw") * 180 / M_PI);
  CHECK((back - R).norm() < 1e-12);
}
