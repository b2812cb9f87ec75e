#include "models/actors/actor.hpp"

#include <catch2/catch.hpp>
#include <map>

#include "devs/simulator.hpp"
#include "scene/assembler.hpp"
#include "scene/scene_loader.hpp"
#include "support/record_collector.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;

TEST_CASE("actors start at a time, after all or after any of others, and report it") {
  testing::SceneDir dir;
  auto scene = scene::loadSceneOrThrow(dir.write("s.yaml", R"(schema_version: 1
components:
  m:
    type: multibody
    params:
      dt: 0.01
      bodies: {x: {parent: world, joint: {type: free}, mass: 1, inertia: [1, 1, 1]}}
  a: {type: body_actor, params: {body: x, duration: 2.0, start_at: 1.0}}
  b: {type: body_actor, params: {body: x, duration: 1.0}}
  all: {type: body_actor, params: {body: x, duration: 0.5, after_all: [a, b]}}
  any: {type: body_actor, params: {body: x, duration: 0.25, after_any: [a, b]}}
couplings:
  - {from: a.setpoint, to: m.setpoint}
  - {from: b.setpoint, to: m.setpoint}
  - {from: all.setpoint, to: m.setpoint}
  - {from: any.setpoint, to: m.setpoint}
  - {from: a.finished, to: all.trigger}
  - {from: b.finished, to: all.trigger}
  - {from: a.finished, to: any.trigger}
  - {from: b.finished, to: any.trigger}
)"));
  auto root = scene::assemble(*scene);
  devs::Simulator sim(*root);
  testing::RecordCollector rec(false);
  sim.addListener(rec);
  sim.runUntil(5.0);  // the multibody model steps forever
  std::map<std::string, double> started, finished;
  for (const auto& r : rec.ofKind("out")) {
    if (r.port == "started") started[r.model] = r.t;
    if (r.port == "finished") finished[r.model] = r.t;
  }
  CHECK(started.at("b") == 0.0);
  CHECK(finished.at("b") == 1.0);
  CHECK(started.at("a") == 1.0);
  CHECK(finished.at("a") == 3.0);
  CHECK(started.at("any") == 1.0);   // the first of a, b to finish
  CHECK(finished.at("any") == 1.25);
  CHECK(started.at("all") == 3.0);   // only once both have finished
  CHECK(finished.at("all") == 3.5);
}

TEST_CASE("an actor given two start rules is refused") {
  testing::SceneDir dir;
  const auto r = scene::loadScene(dir.write("s.yaml", R"(schema_version: 1
components:
  a: {type: joint_actor, params: {joint: j, target_deg: 10, speed_deg: 1, start_at: 1, after_any: [b]}}
)"));
  INFO(r.diagnostics.report());
  REQUIRE(r.diagnostics.errorCount() == 1);
  CHECK_THAT(r.diagnostics.all()[0].message, Catch::Contains("only one of start_at"));
}

TEST_CASE("an actor naming an element its model does not have is refused before the run") {
  testing::SceneDir dir;
  const auto r = scene::loadScene(dir.write("s.yaml", R"(schema_version: 1
components:
  m:
    type: multibody
    params:
      dt: 0.01
      bodies: {arm: {parent: world, joint: {name: shoulder, type: revolute}, mass: 1, inertia: [1, 1, 1]}}
  a: {type: joint_actor, params: {joint: sholder, target: 1, speed: 1}}
  lost: {type: wire_actor, params: {rope: hoist, payout: -1, speed: 0.1}}
couplings:
  - {from: a.setpoint, to: m.setpoint}
)"));
  INFO(r.diagnostics.report());
  REQUIRE(r.diagnostics.errorCount() == 2);
  const auto& bad = r.diagnostics.all()[0];
  CHECK(bad.where.line == 8);
  CHECK(bad.keyPath == "components.a.params.joint");
  CHECK_THAT(bad.message, Catch::Contains("'m' has no joint 'sholder'"));
  CHECK(bad.hint == "did you mean 'shoulder'?");
  CHECK_THAT(r.diagnostics.all()[1].message, Catch::Contains("reaches no multibody model"));
}
