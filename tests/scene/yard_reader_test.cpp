// The yard database's keys in scenes: a block by from_db (mass, cog, inertia, mesh, lugs as rope
// points), a rope grade from the catalogue, a crane by facility with its particulars as
// parameters; the scene's own keys override, provenance names table and row; every mistake
// (unknown block, grade, lug or facility; a missing, newer or damaged database; from_db without
// a database) refused at the door with file:line:col and the key path.
#include "scene/yard_reader.hpp"

#include <catch2/catch.hpp>
#include <fstream>

#include "forces/geometry/primitive_meshes.hpp"
#include "run/runner.hpp"
#include "scene/assembler.hpp"
#include "scene/mechanical_systems.hpp"
#include "scene/resolved_listing.hpp"
#include "support/csv_file.hpp"
#include "support/scene_files.hpp"
#include "yard/block_store.hpp"
#include "yard/catalogue.hpp"

using namespace yardsim;
using Catch::Matchers::Contains;
using models::Diagnostic;
using testing::SceneDir;

namespace {

// (folder) => yard.sqlite there: block B (5 t, cog off the origin, a full inertia, a 2x2x2 m box
// mesh, lugs L1 and L2), the rope grade "R 20 mm" and the crane C1 (model crane.yaml)
void makeDatabase(const SceneDir& dir) {
  const yard::Database db = yard::Database::create(dir.file("yard.sqlite"));
  yard::Block b;
  b.name = "B";
  b.mass = 5000.0;
  b.cog = {0.1, 0.2, 0.3};
  b.inertia << 3000, -10, 5, -10, 3200, 7, 5, 7, 3400;
  b.mesh = std::make_shared<const forces::TriangleMesh>(forces::boxMesh({2, 2, 2}));
  b.lugs = {{"L1", {1, 0, 1}, {0, 0, 1}, 1e5}, {"L2", {-1, 0, 1}, {0, 0, 1}, 1e5}};
  yard::insertBlock(db, b);
  dir.write("ropes.csv",
            "name,diameter,construction,EA,MBL,mass_per_metre\n"
            "R 20 mm,0.02,6x19,3.1e7,2.6e5,1.6\n");
  yard::importRopeCatalogue(db, dir.file("ropes.csv"));
  yard::Facility c;
  c.name = "C1";
  c.modelFile = "crane.yaml";
  c.capacity = 2.5e5;
  c.hoistSpeed = 0.1;
  c.hookLoadCurve = {{0, 2.5e5}, {10, 2.0e5}};
  yard::insertFacility(db, c);
}

// (scene text) => the loaded scene beside the database
scene::LoadResult load(const SceneDir& dir, const std::string& text) {
  return scene::loadScene(dir.write("scene.yaml", text));
}

// (result) => its one error
Diagnostic only(const scene::LoadResult& r) {
  INFO(r.diagnostics.report());
  REQUIRE(r.diagnostics.errorCount() == 1);
  for (const auto& d : r.diagnostics.all())
    if (d.severity == Diagnostic::Severity::Error) return d;
  FAIL("no error");
  throw;
}

// (result, key) => its provenance entry, or a failure
const scene::Provenance& provenance(const scene::LoadResult& r, const std::string& key) {
  for (const auto& p : r.scene->provenance)
    if (p.key == key) return p;
  FAIL("no provenance for " << key);
  throw;
}

const char* kHanging = R"(schema_version: 1
database: yard.sqlite
mechanics:
  bodies:
    b:
      parent: world
      joint: {type: free, q0: {xyz: [0, 0, 5]}}
      from_db: B
      mass: 6000
  ropes:
    sling:
      path: [{body: world, point: [1, 0, 10]}, {body: b, point: L1}]
      catalogue: R 20 mm
      L0: 4.0
      mbl: 3.0e5
until: 1
integrator: {method: rk4, dt: 0.001}
)";

}  // namespace

TEST_CASE("a block from the database brings its figures and lugs and the scene overrides them") {
  SceneDir dir;
  makeDatabase(dir);
  const auto r = load(dir, kHanging);
  INFO(r.diagnostics.report());
  REQUIRE(r.scene);
  REQUIRE(r.scene->systems.size() == 1);
  const auto& spec = r.scene->systems[0]->spec;
  REQUIRE(spec.bodies.size() == 1);
  const auto& b = spec.bodies[0];
  CHECK(b.mass == 6000.0);  // the scene's own mass wins
  CHECK(b.com.isApprox(dynamics::Vector3(0.1, 0.2, 0.3), 0.0));
  CHECK(b.inertia(0, 0) == 3000.0);
  CHECK(b.inertia(0, 1) == -10.0);
  CHECK(b.inertia(1, 0) == -10.0);
  CHECK(b.inertia(1, 2) == 7.0);
  CHECK(b.inertia(2, 2) == 3400.0);
  REQUIRE(b.visual.mesh);  // the stored box: 8 corners, 12 triangles
  CHECK(b.visual.mesh->triangles.size() == 12);
  REQUIRE(spec.ropes.size() == 1);
  const auto& rope = spec.ropes[0];
  CHECK(rope.material.ea == 3.1e7);       // the catalogue's
  CHECK(rope.material.mbl == 3.0e5);      // the scene's
  CHECK(rope.material.diameter == 0.02);  // the catalogue's: the capsule of clearance watches
  CHECK(rope.path[1].first == "b");
  CHECK(rope.path[1].second == dynamics::Vector3(1, 0, 1));  // lug L1
  CHECK_THAT(r.scene->database, Contains("yard.sqlite") && Contains("schema 1"));
  CHECK_THAT(provenance(r, "b.mass").source, Contains("the scene") && Contains("5000"));
  CHECK_THAT(provenance(r, "b.com").source, Contains("blocks row 1 'B'"));
  CHECK_THAT(provenance(r, "sling.EA").source, Contains("ropes row 1 'R 20 mm'"));
  CHECK_THAT(provenance(r, "sling.mbl").source, Contains("the scene"));
  CHECK_THAT(provenance(r, "sling.diameter").source, Contains("ropes row 1 'R 20 mm'"));
  CHECK(provenance(r, "sling.diameter").value == "0.02 m");
  CHECK_THAT(provenance(r, "ropes.sling.path[1].point").value, Contains("lug L1"));
  const std::string listing = scene::resolvedListing(*r.scene);
  CHECK_THAT(listing, Contains("database ") &&
                          Contains("b.inertia = [3000, 3200, 3400, -10, 5, 7]") &&
                          Contains("<- blocks row 1 'B'"));
}

TEST_CASE("a catalogue rope's diameter reaches the clearance watches of a database scene") {
  // the sling hangs from (1, 0, 10) to lug L1 of b at (1, 0, 6), a vertical axis at x = 1; the
  // post's face is at x = 1.5: the clearance is 0.5 m less the rope's radius (no gravity: at rest)
  auto clearance = [](const std::string& ropeKeys) {
    SceneDir dir;
    makeDatabase(dir);
    auto r = load(dir, R"(schema_version: 1
database: yard.sqlite
mechanics:
  gravity: [0, 0, 0]
  bodies:
    b: {parent: world, joint: {type: free, q0: {xyz: [0, 0, 5]}}, from_db: B}
    post:
      parent: world
      joint: {name: post_fix, type: fixed}
      placement: {xyz: [2, 0, 8]}
      mass: 1000
      inertia: [100, 100, 100]
      geometry: {box: [1, 1, 1]}
  ropes:
    sling: {path: [{body: world, point: [1, 0, 10]}, {body: b, point: L1}], L0: 4.0, )" +
                           ropeKeys + R"(}
clearance:
  rope_post: {between: [sling, post], below: 1.0}
record: {interval: 0.01, channels: ["rope_post.distance"]}
integrator: {method: rk4, dt: 0.001}
)");
    INFO(r.diagnostics.report());
    REQUIRE(r.scene);
    auto root = scene::assemble(*r.scene);
    run::runScene(*r.scene, *root, {dir.path() / "out", 0.02, {}, {}});
    const testing::CsvFile csv((dir.path() / "out" / "timeseries.csv").string());
    const int k = csv.column("rope_post.distance[m]");
    REQUIRE(k >= 0);
    return csv.rows.back()[static_cast<std::size_t>(k)];
  };
  CHECK(clearance("catalogue: R 20 mm") == Approx(0.5 - 0.01).margin(1e-9));
  CHECK(clearance("catalogue: R 20 mm, diameter: 0.03") ==
        Approx(0.5 - 0.015).margin(1e-9));                           // the scene's own wins
  CHECK(clearance("EA: 3.1e7") == Approx(0.5 - 0.02).margin(1e-9));  // rope_diameter 0.04
}

TEST_CASE("a facility includes its model file with its particulars as parameters") {
  SceneDir dir;
  makeDatabase(dir);
  dir.write("crane.yaml", R"(schema_version: 1
params: {capacity: 1.0, hoist_speed: 1.0, span: 30}
mechanics:
  bodies:
    hook: {parent: world, joint: {type: prismatic, axis: [0, 0, 1]}, mass: $capacity, inertia: [1, 1, 1]}
)");
  auto r = load(dir,
                "schema_version: 1\ndatabase: yard.sqlite\ncomponents:\n  crane: {facility: "
                "C1}\nuntil: 1\nintegrator: {method: rk4, dt: 0.01}\n");
  INFO(r.diagnostics.report());
  REQUIRE(r.scene);
  REQUIRE(r.scene->root.children.size() == 1);
  CHECK_THAT(r.scene->root.children[0]->source, Contains("crane.yaml"));
  CHECK(r.scene->systems[0]->spec.bodies[0].mass == 2.5e5);  // capacity passed as the parameter
  CHECK_THAT(provenance(r, "crane.params.capacity").source, Contains("facilities row 1 'C1'"));
  // C1 has a hook-load curve, but this model has no hoist rope: said, and not checked
  CHECK(r.scene->hookLoads.empty());
  CHECK_THAT(r.diagnostics.report(), Contains("warning") && Contains("components.crane") &&
                                         Contains("has a hook-load curve but no hoist rope"));
  // the scene's own parameter wins over the particular
  r = load(dir,
           "schema_version: 1\ndatabase: yard.sqlite\ncomponents:\n"
           "  crane: {facility: C1, params: {capacity: 7}}\nuntil: 1\nintegrator: {method: rk4, "
           "dt: 0.01}\n");
  INFO(r.diagnostics.report());
  REQUIRE(r.scene);
  CHECK(r.scene->systems[0]->spec.bodies[0].mass == 7.0);
  CHECK_THAT(provenance(r, "crane.params.capacity").source, Contains("the scene"));
}

TEST_CASE("unknown blocks grades lugs and facilities are refused at their place") {
  SceneDir dir;
  makeDatabase(dir);
  auto edit = [](std::string text, const std::string& from, const std::string& to) {
    text.replace(text.find(from), from.size(), to);
    return text;
  };
  Diagnostic d = only(load(dir, edit(kHanging, "from_db: B", "from_db: BB")));
  CHECK(d.where.line == 8);
  CHECK(d.where.column == 16);
  CHECK(d.keyPath == "mechanics.bodies.b.from_db");
  CHECK_THAT(d.message, Contains("unknown block 'BB'") && Contains("the blocks are B"));
  d = only(load(dir, edit(kHanging, "catalogue: R 20 mm", "catalogue: R 22 mm")));
  CHECK(d.where.line == 13);
  CHECK(d.keyPath == "mechanics.ropes.sling.catalogue");
  CHECK_THAT(d.message, Contains("unknown rope grade 'R 22 mm'"));
  CHECK_THAT(d.hint, Contains("R 20 mm"));
  d = only(load(dir, edit(kHanging, "point: L1", "point: L3")));
  CHECK(d.where.line == 12);
  CHECK(d.keyPath == "mechanics.ropes.sling.path[1].point");
  CHECK_THAT(d.message, Contains("unknown lug 'L3'") && Contains("the lugs are L1, L2"));
  d = only(load(
      dir, "schema_version: 1\ndatabase: yard.sqlite\ncomponents:\n  crane: {facility: C2}\n"));
  CHECK(d.where.line == 4);
  CHECK(d.keyPath == "components.crane.facility");
  CHECK_THAT(d.message, Contains("unknown facility 'C2'") && Contains("C1"));
  const auto r = load(dir, edit(kHanging, "database: yard.sqlite\n", ""));
  REQUIRE(r.diagnostics.errorCount() == 2);  // from_db and catalogue both need it
  d = r.diagnostics.all()[0];
  CHECK(d.keyPath == "mechanics.bodies.b.from_db");
  CHECK_THAT(d.message, Contains("name it at the scene root"));
  CHECK(r.diagnostics.all()[1].keyPath == "mechanics.ropes.sling.catalogue");
}

TEST_CASE("a missing newer or damaged database is refused naming the file") {
  SceneDir dir;
  makeDatabase(dir);
  auto withDb = [&](const std::string& file) {
    std::string text = kHanging;
    text.replace(text.find("yard.sqlite"), 11, file);
    return only(load(dir, text));
  };
  Diagnostic d = withDb("nowhere.sqlite");
  CHECK(d.where.line == 2);
  CHECK(d.keyPath == "database");
  CHECK_THAT(d.message, Contains("nowhere.sqlite") && Contains("no such database file"));
  {
    const yard::Database db = yard::Database::create(dir.file("newer.sqlite"));
    db.execute("PRAGMA user_version = " + std::to_string(yard::kSchemaVersion + 1));
  }
  d = withDb("newer.sqlite");
  CHECK_THAT(d.message, Contains("newer.sqlite") && Contains("schema version"));
  std::ofstream(dir.file("damaged.sqlite")) << "SQLite format 3 but not really a database at all";
  d = withDb("damaged.sqlite");
  CHECK_THAT(d.message, Contains("damaged.sqlite") && Contains("not a readable yardsim database"));
}

TEST_CASE("the database path may come from an environment variable") {
  SceneDir dir;
  makeDatabase(dir);
  std::filesystem::create_directories(dir.path() / "scenes");
  std::string text = kHanging;
  text.replace(text.find("database: yard.sqlite"), 21,
               "database: {env: YARDSIM_TEST_DB, default: missing.sqlite}");
  const auto file = dir.write("scenes/scene.yaml", text);
  ::setenv("YARDSIM_TEST_DB", dir.file("yard.sqlite").c_str(), 1);
  auto r = scene::loadScene(file);
  INFO(r.diagnostics.report());
  CHECK(r.scene);
  ::unsetenv("YARDSIM_TEST_DB");
  r = scene::loadScene(file);  // the default, relative to the scene file, does not exist
  REQUIRE_FALSE(r.scene);
  CHECK_THAT(r.diagnostics.report(), Contains("scenes/missing.sqlite"));
}
