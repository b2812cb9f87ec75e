// The `added_mass` key of a body: a given 6x6 (naval order, about a point) reaches the model
// moved to [angular; linear] about the body origin; a hull mesh next to the YAML file is solved
// by the panel solver at the body's initial pose; bad input is refused with file:line:column.
#include "scene/mechanics_reader.hpp"
#include "mechanics/build.hpp"
#include "scene/added_mass_reader.hpp"

#include <catch2/catch.hpp>

#include "dynamics/added_mass.hpp"
#include "forces/geometry/mesh_io.hpp"
#include "forces/geometry/primitive_meshes.hpp"
#include "forces/hydro/added_mass.hpp"
#include "scene/scene_loader.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;

namespace {

scene::LoadResult load(const testing::SceneDir& dir, const std::string& body) {
  return scene::loadScene(dir.write("s.yaml", "schema_version: 1\ncomponents:\n  m:\n    type: multibody\n"
                                               "    params:\n      dt: 0.01\n      bodies:\n"
                                               "        barge:\n          parent: world\n          joint: {type: free, q0: {xyz: [0, 0, 0]}}\n"
                                               "          mass: 1000\n          inertia: [100, 200, 300]\n" + body));
}

mechanics::BuiltMechanics built(const scene::LoadResult& r) {
  const auto& inst = *r.scene->root.child("m");
  return mechanics::buildMechanics(scene::parseMechanics(inst.params, [](auto&&...) { FAIL("unexpected"); }));
}

}  // namespace

TEST_CASE("a given added mass about a point reaches the model about the body origin") {
  testing::SceneDir dir;
  const auto r = load(dir, R"(          added_mass:
            about: [1, 0, -0.5]
            matrix:
              - [100, 0, 0, 0, 0, 0]
              - [0, 200, 0, 0, 0, 0]
              - [0, 0, 900, 0, 40, 0]
              - [0, 0, 0, 50, 0, 0]
              - [0, 0, 40, 0, 70, 0]
              - [0, 0, 0, 0, 0, 30]
)");
  INFO(r.diagnostics.report());
  REQUIRE(r.scene);
  const auto b = built(r);
  dynamics::Matrix6 naval;
  naval << 100, 0, 0, 0, 0, 0, 0, 200, 0, 0, 0, 0, 0, 0, 900, 0, 40, 0, 0, 0, 0, 50, 0, 0, 0, 0, 40, 0, 70, 0, 0, 0, 0, 0, 0, 30;
  REQUIRE(b.model.hasAddedMass[1]);
  CHECK((b.model.addedMass[1] - dynamics::addedMassAboutOrigin(naval, dynamics::Vector3(1, 0, -0.5))).norm() < 1e-12);
  // heave added mass 900 kg on the linear z entry ([angular; linear])
  CHECK(b.model.addedMass[1](5, 5) == Approx(900.0));
}

TEST_CASE("an added mass computed from a hull next to the YAML file") {
  testing::SceneDir dir;
  // a 10 x 4 x 2 m pontoon, body origin at mid-depth: at q0 = 0 it floats at 1 m draft
  dir.write("hulls/README", "hull meshes\n");
  forces::writeObj(forces::boxMesh(dynamics::Vector3(10, 4, 2), 5, 2, 2), dir.file("hulls/pontoon.obj"));
  const auto r = load(dir, "          added_mass: {hull: hulls/pontoon.obj, rho: 1000}\n");
  INFO(r.diagnostics.report());
  REQUIRE(r.scene);
  const auto b = built(r);
  const dynamics::Matrix6 A = forces::hydro::floatingAddedMass(
      forces::hydro::panelMesh(forces::boxMesh(dynamics::Vector3(10, 4, 2), 5, 2, 2)), {}, 1000.0);
  CHECK((b.model.addedMass[1] - dynamics::addedMassAboutOrigin(0.5 * (A + A.transpose()), dynamics::Vector3::Zero())).norm() <
        1e-9 * A.norm());
  CHECK(b.model.addedMass[1](5, 5) > 0.0);
}

TEST_CASE("a hull that follows its draft may start dry and keeps no constant matrix") {
  testing::SceneDir dir;
  // the pontoon 3 m above the water: dry at q0, its table computed at 0.5 and 1 m draft
  forces::writeObj(forces::boxMesh(dynamics::Vector3(10, 4, 2), 5, 2, 2), dir.file("pontoon.obj"));
  const std::string body = "          added_mass: {hull: pontoon.obj, follow_draft: [0.5, 1.0]}\n";
  const auto r =
      scene::loadScene(dir.write("s.yaml",
                                 "schema_version: 1\ncomponents:\n  m:\n    type: multibody\n"
                                 "    params:\n      dt: 0.01\n      bodies:\n"
                                 "        barge:\n          parent: world\n          joint: {type: "
                                 "free, q0: {xyz: [0, 0, 4]}}\n"
                                 "          mass: 1000\n          inertia: [100, 200, 300]\n" +
                                     body));
  INFO(r.diagnostics.report());
  REQUIRE(r.scene);
  const auto b = built(r);
  CHECK_FALSE(b.model.hasAddedMass[1]);
  REQUIRE(b.draftAddedMass.size() == 1);
  CHECK(b.draftAddedMass[0].body == "barge");
  CHECK(b.draftAddedMass[0].table->drafts == std::vector<double>{0.5, 1.0});
  // at 1 m draft (the origin at the water level) the table holds the constant path's matrix
  const dynamics::Matrix6 A = forces::hydro::floatingAddedMass(
      forces::hydro::panelMesh(forces::boxMesh(dynamics::Vector3(10, 4, 2), 5, 2, 2)), {}, 1025.0);
  CHECK((b.draftAddedMass[0].table->A_B[1] -
         dynamics::addedMassAboutOrigin(0.5 * (A + A.transpose()), dynamics::Vector3::Zero()))
            .norm() < 1e-9 * A.norm());
}

TEST_CASE("a hull above the water at the initial position is refused naming the body") {
  testing::SceneDir dir;
  forces::writeObj(forces::boxMesh(dynamics::Vector3(10, 4, 2), 5, 2, 2), dir.file("pontoon.obj"));
  const auto r = scene::loadScene(dir.write("s.yaml", R"(schema_version: 1
components:
  m:
    type: multibody
    params:
      dt: 0.01
      bodies:
        barge:
          parent: world
          joint: {type: free, q0: {xyz: [0, 0, 5]}}
          mass: 1000
          inertia: [100, 200, 300]
          added_mass: {hull: pontoon.obj}
)"));
  INFO(r.diagnostics.report());
  REQUIRE(r.diagnostics.errorCount() == 1);
  CHECK_THAT(r.diagnostics.all()[0].message, Catch::Contains("body 'barge'") && Catch::Contains("dry"));
}

TEST_CASE("a dry hull in a scene's mechanics is reported at its added_mass, not at 1:1") {
  testing::SceneDir dir;
  forces::writeObj(forces::boxMesh(dynamics::Vector3(10, 4, 2), 5, 2, 2), dir.file("pontoon.obj"));
  const auto r = scene::loadScene(dir.write("s.yaml", R"(schema_version: 1
integrator: {method: rk4, dt: 0.01}
mechanics:
  bodies:
    barge:
      parent: world
      joint: {type: free, q0: {xyz: [0, 0, 5]}}
      mass: 1000
      inertia: [100, 200, 300]
      added_mass: {hull: pontoon.obj}
until: 1
)"));
  INFO(r.diagnostics.report());
  REQUIRE(r.diagnostics.errorCount() == 1);
  const auto& d = r.diagnostics.all()[0];
  CHECK_THAT(d.message, Catch::Contains("body 'barge'") && Catch::Contains("dry"));
  CHECK(d.keyPath == "mechanics.bodies.barge.added_mass");
  CHECK(d.where.line == 10);  // the hull's file name
  CHECK(d.where.column == 26);
}

TEST_CASE("bad added mass input is refused with its position") {
  testing::SceneDir dir;
  dir.write("open.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  struct Case {
    std::string yaml, key, message;
    int line;
  };
  // the body's own keys end on line 12; added_mass starts on line 13
  const std::vector<Case> cases{
      {"          added_mass: {matrix: [[1, 0, 0, 0, 0, 0]]}\n", "bodies.barge.added_mass.matrix",
       "6 rows of 6 numbers", 13},
      {"          added_mass:\n            matrix:\n              - [1, 0, 0, 0, 0, 0]\n           "
       "   - [0, 1, 0, 0, 0, 0]\n"
       "              - [0, 0, 1, 0, 0, 0]\n              - [0, 0, 0, 1, 0, 0]\n              - "
       "[0, 0, 0, 0, 1, 0]\n"
       "              - [0, 0, 0, 0, 7, 1]\n",
       "bodies.barge.added_mass.matrix", "not symmetric: row 5 column 6",
       15},  // first row's first number
      {"          added_mass: {matrix: [[1, 0, 0, 0, 0, 0], [0, 1, 0, 0, 0, 0], [0, 0, 1, 0, 0, "
       "0], [0, 0, 0, 1, 0, 0], "
       "[0, 0, 0, 0, 1, 0], [0, 0, 0, 0, x, 1]]}\n",
       "bodies.barge.added_mass.matrix[5][4]", "expected a number", 13},
      {"          added_mass: {hull: none.obj}\n", "bodies.barge.added_mass.hull", "none.obj", 13},
      {"          added_mass: {hull: open.obj}\n", "bodies.barge.added_mass.hull", "open.obj", 13},
      {"          added_mass: {hull: open.obj, matrix: [[1]]}\n", "bodies.barge.added_mass",
       "exactly one of", 13},
      {"          added_mass: {matrx: [[1]]}\n", "bodies.barge.added_mass.matrx",
       "did you mean 'matrix'?", 13},
      {"          added_mass: {hull: open.obj, follow_draft: 2}\n",
       "bodies.barge.added_mass.follow_draft", "expected a list of drafts in m", 13},
      {"          added_mass:\n            hull: open.obj\n            follow_draft: [0.5, x]\n",
       "bodies.barge.added_mass.follow_draft[1]", "expected a number", 15},
      {"          added_mass:\n            hull: open.obj\n            follow_draft: [0, 1]\n",
       "bodies.barge.added_mass.follow_draft[0]", "expected a draft > 0 m", 15},
      {"          added_mass:\n            hull: open.obj\n            follow_draft: [1, 2, 1.5]\n",
       "bodies.barge.added_mass.follow_draft[2]", "greater than the one before", 15},
      {"          added_mass: {matrix: [[1]], follow_draft: [1]}\n",
       "bodies.barge.added_mass.follow_draft", "'follow_draft' goes with 'hull'", 13},
  };
  for (const Case& c : cases) {
    INFO(c.yaml);
    const auto r = load(dir, c.yaml);
    INFO(r.diagnostics.report());
    REQUIRE(r.diagnostics.errorCount() >= 1);
    const auto& d = r.diagnostics.all()[0];
    CHECK(d.keyPath == "components.m.params." + c.key);
    CHECK_THAT(d.message, Catch::Contains(c.message));
    CHECK(d.where.line == c.line);
    CHECK(d.where.column > 0);
    CHECK(d.where.file.find("s.yaml") != std::string::npos);
  }
}
