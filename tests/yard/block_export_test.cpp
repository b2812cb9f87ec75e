// A block exported as YAML and OBJ: the numbers read back to the last digit.
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

#include "forces/geometry/mesh_io.hpp"
#include "forces/geometry/primitive_meshes.hpp"
#include "support/scene_files.hpp"
#include "yard/block_export.hpp"

using namespace yardsim::yard;
using Catch::Matchers::Contains;
using yardsim::dynamics::Vector3;
using yardsim::testing::SceneDir;

TEST_CASE("an exported block's YAML states every figure and its OBJ is the stored mesh") {
  SceneDir dir;
  Block b;
  b.name = "B1";
  b.project = "P\"7";
  b.mass = 1.0 / 3.0 * 1e6;
  b.cog = Vector3(0.1, 0.2, 0.3);
  b.inertia = Vector3(1e6, 2e6, 2.5e6).asDiagonal();
  b.inertia(0, 1) = b.inertia(1, 0) = -1.25e4;
  b.mesh = std::make_shared<const yardsim::forces::TriangleMesh>(
      yardsim::forces::boxMesh(Vector3(2, 3, 4)));
  b.lugs = {{"L1", Vector3(1, 1.5, 2), Vector3(0, 0, 1), 5e5}};
  const std::string yaml = exportBlock(b, dir.file("out"));
  std::ifstream in(yaml);
  std::stringstream text;
  text << in.rdbuf();
  CHECK_THAT(text.str(),
             Contains("mass: 333333.33333333331") && Contains("com: [0.10000000000000001, ") &&
                 Contains("inertia: [1000000, 2000000, 2500000, -12500, 0, 0]") &&
                 Contains("project: \"P\\\"7\"") && Contains("geometry: {mesh: \"B1.obj\"}") &&
                 Contains("\"L1\": {point: [1, 1.5, 2], direction: [0, 0, 1], swl: 500000}"));
  const auto mesh = yardsim::forces::readClosedMesh(dir.file("out/B1.obj"));
  CHECK(mesh.vertices == b.mesh->vertices);
}
