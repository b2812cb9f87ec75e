// Blocks stored and read back whole (figures, mesh, lugs), and the refusals on the way in.
#include <catch2/catch.hpp>

#include "forces/geometry/primitive_meshes.hpp"
#include "support/scene_files.hpp"
#include "yard/block_store.hpp"

using namespace yardsim::yard;
using Catch::Matchers::Contains;
using yardsim::dynamics::Matrix3;
using yardsim::dynamics::Vector3;
using yardsim::testing::SceneDir;

namespace {
Block sample() {
  Block b;
  b.name = "P0025-S03S";
  b.project = "P0025";
  b.mass = 920e3;
  b.cog = Vector3(1.5, -0.25, 3.0);
  b.inertia << 4e7, 1e5, 2e5, 1e5, 5e7, 3e5, 2e5, 3e5, 6e7;
  b.mesh = std::make_shared<const yardsim::forces::TriangleMesh>(
      yardsim::forces::boxMesh(Vector3(20, 15, 6)));
  b.lugs = {{"L1", Vector3(8, 5, 3), Vector3(0, 0, 2), 120e4},
            {"L2", Vector3(-8, 5, 3), Vector3(0, 0, 1), 120e4}};
  b.weightStatus = "weighed";
  b.source = "test";
  return b;
}
}  // namespace

TEST_CASE("a block with mesh and lugs reads back exactly, lug directions made unit") {
  SceneDir dir;
  const std::string path = dir.file("yard.sqlite");
  insertBlock(Database::create(path), sample());
  const Database db = Database::openReadOnly(path);
  const Block b = getBlock(db, "P0025-S03S");
  const Block s = sample();
  CHECK(b.project == "P0025");
  CHECK(b.mass == s.mass);
  CHECK(b.cog == s.cog);
  CHECK(b.inertia == s.inertia);
  REQUIRE(b.mesh);
  CHECK(b.mesh->vertices == s.mesh->vertices);
  REQUIRE(b.lugs.size() == 2);
  CHECK(b.lugs[0].name == "L1");
  CHECK(b.lugs[0].direction == Vector3(0, 0, 1));
  CHECK(b.lugs[1].position == Vector3(-8, 5, 3));
  CHECK(b.weightStatus == "weighed");
  CHECK(blockNames(db) == std::vector<std::string>{"P0025-S03S"});
  CHECK_FALSE(findBlock(db, "nothing"));
  CHECK_THROWS_WITH(getBlock(db, "P0025-S3S"),
                    Contains("unknown block 'P0025-S3S'") && Contains("P0025-S03S"));
}

TEST_CASE(
    "duplicates, negative masses, unphysical inertias and bad lugs are refused, nothing "
    "half-stored") {
  SceneDir dir;
  const Database db = Database::create(dir.file("yard.sqlite"));
  insertBlock(db, sample());
  CHECK_THROWS_WITH(insertBlock(db, sample()), Contains("already exists"));
  Block b = sample();
  b.name = "B2";
  b.mass = -1;
  CHECK_THROWS_WITH(insertBlock(db, b), Contains("mass must be"));
  b.mass = 1e3;
  b.inertia = Vector3(1, 1, 5).asDiagonal();
  CHECK_THROWS_WITH(insertBlock(db, b), Contains("not physical"));
  b.inertia = Vector3(1, 1, 1).asDiagonal();
  b.lugs[1].swl = 0;
  CHECK_THROWS_WITH(insertBlock(db, b), Contains("lug 'L2'"));
  b.lugs[1] = b.lugs[0];  // the same lug name twice: SQLite's key refuses it, the block goes too
  CHECK_THROWS_AS(insertBlock(db, b), DatabaseError);
  CHECK(blockNames(db) == std::vector<std::string>{"P0025-S03S"});
}
