#include "scene/mechanics_reader.hpp"
#include "mechanics/build.hpp"
#include "mechanics/description.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <vector>

#include "scene/scene_loader.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;

namespace {
scene::LoadResult load(const testing::SceneDir& dir, const std::string& bodies) {
  return scene::loadScene(dir.write("s.yaml", "schema_version: 1\ncomponents:\n  m:\n    type: multibody\n"
                                               "    params:\n      dt: 0.01\n      bodies:\n" + bodies));
}
}  // namespace

TEST_CASE("multibody bodies are checked with positions inside the params") {
  testing::SceneDir dir;
  const auto r = load(dir, R"(        a:
          parent: world
          joint: {type: revolut, axis: [0, 1, 0]}
          mass: 1
          inertia: [1, 1, 1]
        b:
          parent: c
          joint: {type: revolute}
          mass: -2
          inertia: [1, 1, 1]
)");
  INFO(r.diagnostics.report());
  REQUIRE(r.diagnostics.errorCount() == 3);
  const auto& d = r.diagnostics.all();
  CHECK(d[0].keyPath == "components.m.params.bodies.a.joint.type");
  CHECK(d[0].where.line == 10);
  CHECK_THAT(d[0].message, Catch::Contains("did you mean 'revolute'?"));
  CHECK(d[1].keyPath == "components.m.params.bodies.b.mass");
  CHECK(d[1].where.line == 16);
  CHECK(d[2].keyPath == "components.m.params.bodies.b.parent");
  CHECK(d[2].where.line == 14);
}

TEST_CASE("an inertia that violates the triangle inequality is refused naming the body") {
  testing::SceneDir dir;
  const auto r = load(dir, R"(        slab:
          parent: world
          joint: {type: revolute}
          mass: 1
          inertia: [1, 1, 5]
)");
  INFO(r.diagnostics.report());
  REQUIRE(r.diagnostics.errorCount() == 1);
  CHECK_THAT(r.diagnostics.all()[0].message, Catch::Contains("slab"));
}

TEST_CASE("initial positions in degrees and placements build into the model") {
  testing::SceneDir dir;
  const auto r = load(dir, R"(        a:
          parent: world
          joint: {name: j0, type: revolute, axis: [0, 1, 0], q0_deg: 30, v0: 0.5}
          placement: {xyz: [0, 0, 2]}
          mass: 1
          inertia: [1, 1, 1]
)");
  REQUIRE(r.scene);
  const auto& inst = *r.scene->root.child("m");
  const auto spec = scene::parseMechanics(inst.params, [](auto&&...) { FAIL("unexpected"); });
  const auto built = mechanics::buildMechanics(spec);
  CHECK(built.model.nbodies == 2);
  CHECK(built.q0[0] == Approx(M_PI / 6));
  CHECK(built.v0[0] == 0.5);
  CHECK(built.jointNames[1] == "j0");
  CHECK(built.model.X_PJ[1].p.z() == 2.0);
}

TEST_CASE("visual geometry: each shape parsed, and every mistake refused at its place") {
  testing::SceneDir dir;
  const std::string body = "          parent: world\n          joint: {type: fixed}\n          mass: 1\n"
                           "          inertia: [1, 1, 1]\n";
  const auto good = load(dir, "        a:\n" + body + "          geometry: {box: [1, 2, 3]}\n" +
                                  "        b:\n" + body +
                                  "          geometry: {cylinder: {radius: 0.5, length: 4}, pose: {xyz: [0, 0, 1]}}\n" +
                                  "        c:\n" + body + "          geometry: {sphere: 0.25}\n" +
                                  "        d:\n" + body);
  REQUIRE(good.scene);
  using Shape = mechanics::MechanicsSpec::Visual::Shape;
  const auto spec = scene::parseMechanics(good.scene->root.child("m")->params, [](auto&&...) { FAIL("unexpected"); });
  const auto built = mechanics::buildMechanics(spec);
  REQUIRE(built.visuals.size() == 5);
  CHECK(built.visuals[1].shape == Shape::Box);
  CHECK(built.visuals[1].size == dynamics::Vector3(1, 2, 3));
  CHECK(built.visuals[2].shape == Shape::Cylinder);
  CHECK(built.visuals[2].size.head<2>() == Eigen::Vector2d(0.5, 4));
  CHECK(built.visuals[2].posed);
  CHECK(built.visuals[2].X_BG.p.z() == 1.0);
  CHECK(built.visuals[3].shape == Shape::Sphere);
  CHECK(built.visuals[3].size[0] == 0.25);
  CHECK(built.visuals[4].shape == Shape::Auto);

  const auto bad = load(dir, "        a:\n" + body + "          geometry: {box: [1, 2]}\n" +
                                 "        b:\n" + body + "          geometry: {sphere: -1}\n" +
                                 "        c:\n" + body + "          geometry: {box: [1, 1, 1], sphere: 1}\n" +
                                 "        d:\n" + body + "          geometry: {cylinder: {radius: 1}}\n" +
                                 "        e:\n" + body + "          geometry: {cone: 1}\n");
  INFO(bad.diagnostics.report());
  REQUIRE(bad.diagnostics.errorCount() == 5);
  const auto& d = bad.diagnostics.all();
  CHECK(d[0].keyPath == "components.m.params.bodies.a.geometry.box");
  CHECK_THAT(d[0].message, Catch::Contains("list of 3 numbers"));
  CHECK(d[1].keyPath == "components.m.params.bodies.b.geometry.sphere");
  CHECK(d[1].where.line == 19);
  CHECK_THAT(d[1].message, Catch::Contains("must be > 0 m"));
  CHECK(d[2].keyPath == "components.m.params.bodies.c.geometry");
  CHECK_THAT(d[2].message, Catch::Contains("more than one shape"));
  CHECK(d[3].keyPath == "components.m.params.bodies.d.geometry.cylinder.length");
  CHECK(d[4].keyPath == "components.m.params.bodies.e.geometry.cone");
  CHECK_THAT(d[4].message, Catch::Contains("unknown key 'cone'"));
}

TEST_CASE("a rope's parts are a whole number and its breaking load, when given, is positive") {
  testing::SceneDir dir;
  auto scene = [&](const std::string& rope) {
    return scene::loadScene(dir.write("s.yaml", R"(schema_version: 1
integrator: {method: rk4, dt: 0.01}
mechanics:
  bodies:
    block: {parent: world, joint: {type: prismatic, axis: [0, 0, 1], q0: -5}, mass: 10, inertia: [1, 1, 1]}
  ropes:
    hoist: {path: [{point: [0, 0, 0]}, {body: block, point: [0, 0, 0]}], EA: 1.0e6, L0: 5, )" + rope + "}\n"));
  };
  CHECK(scene("parts: 2").scene);
  CHECK(scene("mbl: 1e5").scene);
  // (1e9 and 2.1e10 beyond an int: refused before any cast, which the fuzzer found under UBSan)
  for (const std::string bad : {"parts: 2.5", "parts: 0", "parts: 1e9", "parts: 2.1e10",
                                "parts: .nan", "mbl: 0", "mbl: -1"}) {
    const auto r = scene(bad);
    INFO(bad << "\n" << r.diagnostics.report());
    CHECK_FALSE(r.scene);
    CHECK(r.diagnostics.report().find("s.yaml:7:") != std::string::npos);
    CHECK(r.diagnostics.report().find(bad.substr(0, bad.find(':'))) != std::string::npos);
  }
}

TEST_CASE(
    "missing keys and lists where a name belongs are located errors inside a multibody component") {
  testing::SceneDir dir;
  // issue 14: each of these was "internal error: invalid node; first invalid key" (exit 3)
  struct Case {
    std::string bodies, keyPath, message;
    int line;
  };
  const std::string ok =
      "        a:\n          parent: world\n          joint: {type: revolute, axis: [0, 1, 0]}\n"
      "          mass: 1\n          inertia: [1, 1, 1]\n";
  const std::vector<Case> cases{
      {"        a:\n          parent: world\n          joint: {type: revolute}\n          inertia: "
       "[1, 1, 1]\n",
       "components.m.params.bodies.a", "missing required key 'mass'", 9},
      {"        a:\n          parent: world\n          mass: 1\n          inertia: [1, 1, 1]\n",
       "components.m.params.bodies.a", "missing required key 'joint'", 9},
      {"        a:\n          parent: world\n          joint: {axis: [0, 1, 0]}\n          mass: "
       "1\n"
       "          inertia: [1, 1, 1]\n",
       "components.m.params.bodies.a.joint", "missing required key 'type'", 10},
      {"        a:\n          parent: [world]\n          joint: {type: fixed}\n          mass: 1\n"
       "          inertia: [1, 1, 1]\n",
       "components.m.params.bodies.a.parent", "expected a name, got a list", 9},
      {ok + "      ropes:\n        r: {EA: 1.0e6, L0: 1}\n", "components.m.params.ropes.r",
       "missing required key 'path'", 14},
      {ok + "      ropes:\n        r: {path: [{point: [0, 0, 1]}, {body: [a], point: [0, 0, 0]}], "
            "EA: 1.0e6, L0: 1}\n",
       "components.m.params.ropes.r.path[1].body", "expected a name, got a list", 14},
      {ok + "      ropes:\n        r: {path: [{point: [0, 0, 1]}, {body: a, point: [0, 0, 0]}], "
            "L0: 1}\n",
       "components.m.params.ropes.r", "missing required key 'EA'", 14},
  };
  for (const auto& c : cases) {
    const auto r = load(dir, c.bodies);
    INFO(c.bodies << r.diagnostics.report());
    REQUIRE(r.diagnostics.errorCount() == 1);
    const auto& d = r.diagnostics.all().front();
    CHECK(d.keyPath == c.keyPath);
    CHECK_THAT(d.message, Catch::Contains(c.message));
    CHECK(d.where.line == c.line);
    CHECK(d.where.column > 0);
  }
}

TEST_CASE("a load without series and an equalizer without branches are located errors") {
  // (fuzzer finding, scene_loader_fuzz) a missing list read as a list threw yaml-cpp's InvalidNode
  testing::SceneDir dir;
  const std::string ok =
      "        a:\n          parent: world\n          joint: {type: free}\n          mass: 1\n"
      "          inertia: [1, 1, 1]\n";
  for (const auto& [extra, key] : std::vector<std::pair<std::string, std::string>>{
           {"      loads:\n        push: {body: a}\n", "components.m.params.loads.push.series"},
           {"      equalizers:\n        eq: {sheave: {body: a}, EA: 1.0e6, L0: 1}\n",
            "components.m.params.equalizers.eq.branches"}}) {
    const auto r = load(dir, ok + extra);
    INFO(r.diagnostics.report());
    REQUIRE(r.diagnostics.errorCount() == 1);
    CHECK(r.diagnostics.all().front().keyPath == key);
    CHECK(r.diagnostics.all().front().where.line == 14);
  }
}

TEST_CASE("a coordinate or size beyond 1e6 m is refused at its value: placement and com and box") {
  testing::SceneDir dir;
  const auto r = load(dir, R"(        a:
          parent: world
          joint: {type: revolute}
          placement: {xyz: [0, 0, 1.0e7]}
          mass: 1
          com: [1.0e300, 0, 0]
          inertia: [1, 1, 1]
          geometry: {box: [1, 1, 2.0e6]}
        b:
          parent: a
          joint: {type: revolute}
          placement: {xyz: [0, 0, -1.0e6]}
          mass: 1
          inertia: [1, 1, 1]
)");
  INFO(r.diagnostics.report());
  REQUIRE(r.diagnostics.errorCount() == 3);  // b's -1e6 m is inside the range
  const auto& d = r.diagnostics.all();
  std::vector<std::pair<std::string, int>> got;
  for (const auto& e : d) {
    CHECK_THAT(e.message, Catch::Contains("within ±1e6"));
    got.emplace_back(e.keyPath, e.where.line);
  }
  std::sort(got.begin(), got.end());
  CHECK(got == std::vector<std::pair<std::string, int>>{
                   {"components.m.params.bodies.a.com", 13},
                   {"components.m.params.bodies.a.geometry.box", 15},
                   {"components.m.params.bodies.a.placement.xyz", 11}});
}

TEST_CASE(
    "a multibody component's max_order is a whole number from 0 to 12, refused before any cast") {
  testing::SceneDir dir;
  const std::string body =
      "        a:\n          parent: world\n          joint: {type: revolute, axis: [0, 1, 0]}\n"
      "          mass: 1\n          inertia: [1, 1, 1]\n";
  auto scene = [&](const std::string& order) {
    return scene::loadScene(dir.write("s.yaml",
                                      "schema_version: 1\ncomponents:\n  m:\n    type: multibody\n"
                                      "    params:\n      dt: 0.01\n      method: cvode_adams\n"
                                      "      max_order: " +
                                          order + "\n      bodies:\n" + body));
  };
  CHECK(scene("0").scene);
  CHECK(scene("12").scene);
  // (2.1e10 and 1e300 beyond an int: found by reading the cast, as the fuzzer found the rope's
  // parts)
  for (const std::string bad : {"2.5", "-1", "13", "2.1e10", "1e300"}) {
    const auto r = scene(bad);
    INFO(bad << "\n" << r.diagnostics.report());
    CHECK_FALSE(r.scene);
    REQUIRE(r.diagnostics.errorCount() == 1);
    CHECK(r.diagnostics.all().front().keyPath == "components.m.params.max_order");
    CHECK(r.diagnostics.all().front().where.line == 8);
    CHECK_THAT(r.diagnostics.all().front().message, Catch::EndsWith("got " + bad));
  }
}
