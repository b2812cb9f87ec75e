// `yardsim db`, run as a process: the fixture script builds a database from the examples' data,
// then list, show and export read it; user errors exit 1 with a message naming what is wrong.
#include <sys/wait.h>
#include <catch2/catch.hpp>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "support/scene_files.hpp"
#include "support/shell_command.hpp"
#include "support/test_paths.hpp"

using Catch::Matchers::Contains;

namespace {

using Result = yardsim::testing::ShellResult;
using yardsim::testing::shell;

const std::string kYardsim = YARDSIM_EXE;

// (folder) => the fixture database built there by examples/yard/build_fixture.sh
std::string fixture(const yardsim::testing::SceneDir& dir) {
  const std::string db = dir.file("yard.sqlite");
  const auto r = shell(std::string(YARDSIM_SOURCE_DIR) + "/examples/yard/build_fixture.sh " +
                       kYardsim + " " + db);
  INFO(r.out);
  REQUIRE(r.status == 0);
  return db;
}

}  // namespace

TEST_CASE("the fixture database lists, shows and exports the examples' block, cranes and ropes") {
  yardsim::testing::SceneDir dir;
  const std::string db = fixture(dir);
  auto r = shell(kYardsim + " db --db " + db + " list blocks");
  CHECK(r.status == 0);
  CHECK_THAT(r.out, Contains("GT-BLOCK-920") && Contains("920000 kg") && Contains("calculated"));
  r = shell(kYardsim + " db --db " + db + " list facilities");
  CHECK_THAT(r.out, Contains("GOC201") && Contains("GOC202") && Contains("goliath_crane.yaml"));
  r = shell("env YARDSIM_DB=" + db + " " + kYardsim +
            " db list ropes");  // the database from the environment
  CHECK(r.status == 0);
  CHECK_THAT(r.out, Contains("goliath hoist 6x36 IWRC 54 mm") && Contains("6x36 IWRC 64 mm"));
  r = shell(kYardsim + " db --db " + db + " show GT-BLOCK-920");
  CHECK_THAT(r.out, Contains("Ixx 2.24e+07 Iyy 4.69e+07 Izz 6.38e+07") &&
                        Contains("12 triangles") && Contains("lug L202A") &&
                        Contains("SWL 3e+06 N"));
  r = shell(kYardsim + " db --db " + db + " show GOC201");
  CHECK_THAT(r.out, Contains("hoist speed    0.083 m/s") && Contains("16 m: 6e+06 N"));
  r = shell(kYardsim + " db --db " + db + " export GT-BLOCK-920 -o " + dir.file("out"));
  CHECK(r.status == 0);
  std::ifstream yaml(dir.file("out/GT-BLOCK-920.yaml"));
  std::stringstream text;
  text << yaml.rdbuf();
  CHECK_THAT(text.str(), Contains("mass: 920000") &&
                             Contains("inertia: [22400000, 46900000, 63800000, 0, 0, 0]"));
  CHECK(std::filesystem::exists(dir.path() / "out/GT-BLOCK-920.obj"));
}

TEST_CASE("db user errors exit 1 with a clear message") {
  yardsim::testing::SceneDir dir;
  const std::string db = fixture(dir);
  const std::string cmd = kYardsim + " db --db " + db + " ";
  auto r = shell(cmd + "import-block GT-BLOCK-920 --mass 1 --cog 0,0,0 --inertia 1,1,1");
  CHECK(r.status == 1);
  CHECK_THAT(r.out, Contains("block 'GT-BLOCK-920' already exists"));
  r = shell(cmd + "import-block B --mass -5 --cog 0,0,0 --inertia 1,1,1");
  CHECK(r.status == 1);
  CHECK_THAT(r.out, Contains("mass must be a finite number > 0"));
  r = shell(cmd + "import-block B --mass 5 --cog 0,0,0 --inertia 1,1,3");
  CHECK(r.status == 1);
  CHECK_THAT(r.out, Contains("not physical"));
  r = shell(cmd + "import-block B --step " + dir.file("none.step") + " --density 7850");
  CHECK(r.status == 1);
  CHECK_THAT(r.out, Contains("none.step: no such file"));
  r = shell(cmd + "show NOPE");
  CHECK(r.status == 1);
  CHECK_THAT(r.out, Contains("unknown rope 'NOPE'"));
  r = shell(cmd + "import-rope-catalogue " + std::string(YARDSIM_SOURCE_DIR) +
            "/examples/yard/ropes.csv");
  CHECK(r.status == 1);
  CHECK_THAT(r.out, Contains("ropes.csv:2") && Contains("already in the catalogue"));
  dir.write("foreign.sqlite",
            "not a database at all, just text that is long enough to be read as a header....");
  r = shell(kYardsim + " db --db " + dir.file("foreign.sqlite") + " list blocks");
  CHECK(r.status == 1);
  CHECK_THAT(r.out, Contains("not a readable yardsim database"));
  r = shell(kYardsim + " db init " + db);  // an existing current database: reported, untouched
  CHECK(r.status == 0);
  CHECK_THAT(r.out, Contains("schema version 1"));
  r = shell(kYardsim + " db list blocks");
  CHECK(r.status == 1);
  CHECK_THAT(r.out, Contains("give --db FILE or set YARDSIM_DB"));
}

TEST_CASE(
    "db import-block from a closed OBJ with a density stores the solid's closed-form figures") {
  yardsim::testing::SceneDir dir;
  const std::string db = fixture(dir);
  // a 2 x 3 x 4 m box in a hand-written OBJ: m = 24000 kg, I = m (b^2 + c^2) / 12 ...
  dir.write("box.obj",
            "v 0 0 0\nv 2 0 0\nv 2 3 0\nv 0 3 0\nv 0 0 4\nv 2 0 4\nv 2 3 4\nv 0 3 4\n"
            "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n");
  auto r = shell(kYardsim + " db --db " + db + " import-block BOX --obj " + dir.file("box.obj") +
                 " --density 1000");
  INFO(r.out);
  CHECK(r.status == 0);
  CHECK_THAT(r.out, Contains("24000 kg"));
  r = shell(kYardsim + " db --db " + db + " show BOX");
  CHECK_THAT(r.out,
             Contains("cog            1 1.5 2 m") && Contains("Ixx 50000 Iyy 40000 Izz 26000"));
  // the same box as a STEP file in millimetres (examples/yard/box_2x3x4.step, written by OCCT):
  // the B-rep figures in metres, the mesh its 12 triangles
  r = shell(kYardsim + " db --db " + db + " import-block BOXSTEP --step " +
            std::string(YARDSIM_SOURCE_DIR) + "/examples/yard/box_2x3x4.step --density 1000");
  CHECK(r.status == 0);
  CHECK_THAT(r.out, Contains("24000 kg, 12 triangles"));
  r = shell(kYardsim + " db --db " + db + " show BOXSTEP");
  CHECK_THAT(r.out, Contains("cog            1 1.5 2 m") &&
                        Contains("Ixx 50000 Iyy 40000 Izz 26000") && Contains("STEP B-rep"));
}
