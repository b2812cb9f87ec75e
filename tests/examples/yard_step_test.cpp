// A STEP block in a scene that runs (examples/yard/box_2x3x4.step: a 2 x 3 x 4 m box, corner at
// the origin, written by OCCT in millimetres): once as `geometry: {mesh: box.step}` on a body
// typed by hand, once imported into the yard database with a density (figures from the B-rep)
// and brought in by `from_db` with its lug. Each hangs still (static equilibrium) from one
// rope at the top of its centre of gravity, so the rope carries m g with m = rho V = 1000 kg/m^3
// x 24 m^3; the replay draws the STEP mesh's 12 triangles.
#include <catch2/catch.hpp>

#include "support/csv_file.hpp"
#include "support/glb_file.hpp"
#include "support/scene_files.hpp"
#include "support/shell_command.hpp"
#include "support/test_paths.hpp"

using Catch::Matchers::Contains;
using yardsim::testing::shell;

namespace {

const std::string kYardsim = YARDSIM_EXE;
const std::string kStep = std::string(YARDSIM_SOURCE_DIR) + "/examples/yard/box_2x3x4.step";

// (body keys) => a scene hanging that body from one rope at the point TOP
std::string hanging(const std::string& database, const std::string& body, const std::string& top) {
  return "schema_version: 1\n" + database + R"(mechanics:
  equilibrium: true
  bodies:
    box:
      parent: world
      joint: {type: free}
)" + body +
         R"(  ropes:
    sling: {path: [{body: world, point: [1, 1.5, 10]}, {body: box, point: )" +
         top + R"(}], EA: 1.0e9, L0: 6.0, damping: 1.0e4}
record: {interval: 0.1, channels: ["sling.tension"]}
until: 1
integrator: {method: rk4, dt: 0.001}
)";
}

// (output folder) => the rope's tension at t = 0, N, and the replay's triangles
void check(const yardsim::testing::SceneDir& dir, const std::string& out) {
  const yardsim::testing::CsvFile csv(dir.file(out + "/timeseries.csv"));
  const int col = csv.column("sling.tension[N]");
  REQUIRE(col > 0);
  REQUIRE_FALSE(csv.rows.empty());
  CHECK(csv.rows.front()[static_cast<std::size_t>(col)] == Approx(24000.0 * 9.81).epsilon(1e-6));
  CHECK(csv.rows.back()[static_cast<std::size_t>(col)] == Approx(24000.0 * 9.81).epsilon(1e-6));
  const yardsim::testing::GlbFile glb(dir.file(out + "/replay.glb"));
  std::size_t indices = 0;
  for (const auto& mesh : glb.json["meshes"])
    for (const auto& prim : mesh["primitives"])
      if (prim["indices"])
        indices += glb.json["accessors"][prim["indices"].as<int>()]["count"].as<std::size_t>();
  CHECK(indices >= 12 * 3);  // at least the box's 12 triangles (ropes may add their own)
}

}  // namespace

TEST_CASE("a body whose geometry is a STEP file runs") {
  yardsim::testing::SceneDir dir;
  const auto scene = dir.write("scene.yaml", hanging("", R"(      mass: 24000
      com: [1, 1.5, 2]
      inertia: [50000, 40000, 26000]
      geometry: {mesh: )" + kStep + "}\n",
                                                     "[1, 1.5, 4]"));
  const auto r = shell(kYardsim + " run " + scene.string() + " -o " + dir.file("out"));
  INFO(r.out);
  REQUIRE(r.status == 0);
  check(dir, "out");
}

TEST_CASE("a STEP block imported into the database runs by from_db with its lug") {
  yardsim::testing::SceneDir dir;
  const std::string db = dir.file("yard.sqlite");
  auto r = shell(kYardsim + " db init " + db);
  REQUIRE(r.status == 0);
  r = shell(kYardsim + " db --db " + db + " import-block BOX --step " + kStep +
            " --density 1000 --lug TOP:1,1.5,4:0,0,1:5e5");
  INFO(r.out);
  REQUIRE(r.status == 0);
  const auto scene =
      dir.write("scene.yaml", hanging("database: yard.sqlite\n", "      from_db: BOX\n", "TOP"));
  r = shell(kYardsim + " run " + scene.string() + " -o " + dir.file("out"));
  INFO(r.out);
  REQUIRE(r.status == 0);
  check(dir, "out");
  r = shell(kYardsim + " validate --print-resolved " + scene.string());
  // the B-rep's mass to the last bits (23999.999999999996 kg), shown exactly as used
  CHECK_THAT(r.out, Contains("box.mass = 2") && Contains("kg  <- blocks row 1 'BOX'") &&
                        Contains("ropes.sling.path[1].point = [1, 1.5, 4] m (lug TOP)"));
}
