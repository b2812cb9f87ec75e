#include "scene/coupling_graph.hpp"

#include <catch2/catch.hpp>

#include "scene/scene_loader.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;

TEST_CASE("a loop of zero-delay models is an algebraic loop naming its models") {
  testing::SceneDir dir;
  const auto r = scene::loadScene(dir.write("s.yaml", R"(schema_version: 1
components:
  box:
    coupled:
      inputs: {in: int}
      outputs: {out: int}
      components:
        d1: {type: delay, params: {delay: 0}}
        d2: {type: delay, params: {delay: 0}}
      couplings:
        - {from: in, to: d1.in}
        - {from: d1.out, to: d2.in}
        - {from: d2.out, to: out}
  d3: {type: delay}
couplings:
  - {from: box.out, to: d3.in}
  - {from: d3.out, to: box.in}
)"));
  INFO(r.diagnostics.report());
  REQUIRE(r.diagnostics.errorCount() == 1);
  const auto& msg = r.diagnostics.all()[0].message;
  CHECK_THAT(msg, Catch::Contains("zero-delay algebraic loop"));
  CHECK_THAT(msg, Catch::Contains("box.d1") && Catch::Contains("box.d2") && Catch::Contains("d3"));
}

TEST_CASE("a loop with a delay in it is fine — an unfed input is a warning") {
  testing::SceneDir dir;
  const auto r = scene::loadScene(dir.write("s.yaml", R"(schema_version: 1
components:
  d1: {type: delay, params: {delay: 0}}
  d2: {type: delay, params: {delay: 0.5}}
  lonely: {type: delay}
couplings:
  - {from: d1.out, to: d2.in}
  - {from: d2.out, to: d1.in}
)"));
  INFO(r.diagnostics.report());
  REQUIRE(r.scene);
  REQUIRE(r.diagnostics.all().size() == 1);
  const auto& w = r.diagnostics.all()[0];
  CHECK(w.severity == models::Diagnostic::Severity::Warning);
  CHECK(w.where.line == 5);
  CHECK_THAT(w.message, Catch::Contains("input port 'in' of 'lonely' is not connected"));
}

TEST_CASE("actors waiting for each other in a cycle, or for themselves, are refused naming the cycle") {
  yardsim::testing::SceneDir dir;
  const auto r = yardsim::scene::loadScene(dir.write("s.yaml", R"(schema_version: 1
integrator: {method: rk4, dt: 0.01}
until: 5
mechanics:
  bodies:
    arm:
      parent: world
      joint: {name: hinge, type: revolute, axis: [0, 1, 0]}
      mass: 1
      inertia: [1, 1, 1]
components:
  first: {type: joint_actor, params: {joint: hinge, target_deg: 10, speed_deg: 5, after_all: [second]}}
  second: {type: joint_actor, params: {joint: hinge, target_deg: 20, speed_deg: 5, after_any: [third]}}
  third: {type: joint_actor, params: {joint: hinge, target_deg: 20, speed_deg: 5, after_all: [first]}}
  self: {type: joint_actor, params: {joint: hinge, target_deg: 0, speed_deg: 5, after_all: [self]}}
  fine: {type: joint_actor, params: {joint: hinge, target_deg: 0, speed_deg: 5, after_all: [self]}}
)"));
  CHECK_FALSE(r.scene);
  const std::string report = r.diagnostics.report();
  INFO(report);
  CHECK(report.find("s.yaml:12:94") != std::string::npos);  // at the first actor's start rule
  CHECK(report.find("would never start: first -> second -> third -> first") != std::string::npos);
  CHECK(report.find("s.yaml:15:") != std::string::npos);
  CHECK(report.find("would never start: self -> self") != std::string::npos);
  CHECK(report.find("fine ->") == std::string::npos);  // waits for a cycle, but is not in one
}

TEST_CASE("algebraic loops of one, two and three models, across two levels, each named exactly where it starts") {
  testing::SceneDir dir;
  struct Case {
    std::string yaml, where, message;
  };
  const std::vector<Case> cases{
      {R"(schema_version: 1
components:
  d: {type: delay, params: {delay: 0}}
couplings:
  - {from: d.out, to: d.in}
)", "s.yaml:3:3: error: components.d: ", "zero-delay algebraic loop: d -> d; "},
      {R"(schema_version: 1
components:
  a: {type: delay, params: {delay: 0}}
  b: {type: delay}
couplings:
  - {from: a.out, to: b.in}
  - {from: b.out, to: a.in}
)", "s.yaml:3:3: error: components.a: ", "zero-delay algebraic loop: a -> b -> a; "},
      {R"(schema_version: 1
components:
  top:
    coupled:
      inputs: {in: int}
      outputs: {out: int}
      components:
        mid:
          coupled:
            inputs: {in: int}
            outputs: {out: int}
            components:
              deep: {type: delay}
            couplings:
              - {from: in, to: deep.in}
              - {from: deep.out, to: out}
      couplings:
        - {from: in, to: mid.in}
        - {from: mid.out, to: out}
  back: {type: delay}
couplings:
  - {from: top.out, to: back.in}
  - {from: back.out, to: top.in}
)", "s.yaml:13:15: error: components.top.coupled.components.mid.coupled.components.deep: ",
       "zero-delay algebraic loop: top.mid.deep -> back -> top.mid.deep; "}};
  for (const auto& c : cases) {
    const auto r = scene::loadScene(dir.write("s.yaml", c.yaml));
    const std::string report = r.diagnostics.report();
    INFO(report);
    CHECK_FALSE(r.scene);
    REQUIRE(r.diagnostics.errorCount() == 1);
    CHECK(report.find(c.where + c.message) != std::string::npos);
  }
  // (the three-level loop) => both its models named, the deep one by its full path
  const auto r = scene::loadScene(dir.write("s.yaml", cases[2].yaml));
  CHECK_THAT(r.diagnostics.report(), Catch::Contains("top.mid.deep") && Catch::Contains("back"));
}
