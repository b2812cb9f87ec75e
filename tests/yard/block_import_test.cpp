// A block's figures from a closed mesh and a density, from a stated mass and cog (the solid's
// inertia scaled and moved by parallel axes), and the refusals.
#include <catch2/catch.hpp>

#include "forces/geometry/mesh_io.hpp"
#include "forces/geometry/primitive_meshes.hpp"
#include "support/scene_files.hpp"
#include "yard/block_import.hpp"
#include "yard/database.hpp"

using namespace yardsim::yard;
using Catch::Matchers::Contains;
using yardsim::dynamics::Matrix3;
using yardsim::dynamics::Vector3;
using yardsim::testing::SceneDir;

TEST_CASE("a box mesh with a density gives the closed-form mass, cog and inertia") {
  SceneDir dir;
  // 20 x 15 x 6 m, corner at the origin after a shift
  auto mesh = yardsim::forces::boxMesh(Vector3(20, 15, 6));
  for (auto& v : mesh.vertices) v += Vector3(10, 7.5, 3);
  yardsim::forces::writeObj(mesh, dir.file("block.obj"));
  BlockSource s;
  s.geometry = dir.file("block.obj");
  s.density = 500.0;
  const Block b = blockFromSource("B", s);
  const double m = 500.0 * 20 * 15 * 6;
  CHECK(b.mass == Approx(m).epsilon(1e-12));
  CHECK((b.cog - Vector3(10, 7.5, 3)).norm() < 1e-9);
  CHECK(b.inertia(0, 0) == Approx(m / 12 * (15 * 15 + 6 * 6)).epsilon(1e-10));
  CHECK(b.inertia(2, 2) == Approx(m / 12 * (20 * 20 + 15 * 15)).epsilon(1e-10));
  CHECK(std::abs(b.inertia(0, 1)) < 1e-6 * b.inertia(0, 0));
  CHECK(b.weightStatus == "calculated");
  CHECK(b.mesh->triangles.size() == mesh.triangles.size());
  CHECK_THAT(b.source, Contains("block.obj") && Contains("density"));

  // the same box with a stated mass and a cog 1 m above its centroid: parallel axes
  BlockSource t;
  t.geometry = dir.file("block.obj");
  t.mass = 1e6;
  t.cog = Vector3(10, 7.5, 4);
  const Block c = blockFromSource("C", t);
  CHECK(c.inertia(0, 0) == Approx(1e6 / 12 * (15 * 15 + 6 * 6) + 1e6 * 1.0).epsilon(1e-10));
  CHECK(c.inertia(2, 2) == Approx(1e6 / 12 * (20 * 20 + 15 * 15)).epsilon(1e-10));
}

TEST_CASE("stated figures without geometry, and what is refused") {
  SceneDir dir;
  BlockSource s;
  s.mass = 5e3;
  s.cog = Vector3(0, 0, 1);
  CHECK_THROWS_WITH(blockFromSource("B", s), Contains("needs --inertia"));
  s.inertia = Matrix3(Vector3(1e3, 2e3, 2.5e3).asDiagonal());
  const Block b = blockFromSource("B", s);
  CHECK(b.mass == 5e3);
  CHECK_FALSE(b.mesh);
  s.inertia = Matrix3(Vector3(1e3, 2e3, 4e3).asDiagonal());
  CHECK_THROWS_WITH(blockFromSource("B", s), Contains("not physical"));
  s.mass = -2;
  CHECK_THROWS_WITH(blockFromSource("B", s), Contains("mass must be"));
  BlockSource none;
  CHECK_THROWS_WITH(blockFromSource("B", none), Contains("either --density or --mass"));
  none.density = 7850;
  none.geometry = dir.file("missing.stl");
  CHECK_THROWS_WITH(blockFromSource("B", none), Contains("missing.stl: no such file"));
  // an open mesh (a box with a face missing) is refused by the closed-mesh check
  auto open = yardsim::forces::boxMesh(Vector3(1, 1, 1));
  open.triangles.pop_back();
  yardsim::forces::writeObj(open, dir.file("open.obj"));
  none.geometry = dir.file("open.obj");
  CHECK_THROWS_WITH(blockFromSource("B", none), Contains("open.obj"));
}
