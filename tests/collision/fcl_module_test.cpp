// FCL behind a module (collision/world_backend.hpp): a process linked to yardsim::collision has
// neither FCL nor the module mapped, and counts no FCL world, until it makes its first
// CollisionWorld; that world is FCL's (its counts move, two spheres are as far apart as their
// centres less their radii); a missing module, or a library without the entry, is refused naming
// the file and the fix.
#include <catch2/catch.hpp>

#include <filesystem>

#include "collision/collision_world.hpp"
#include "collision/world_backend.hpp"
#include "support/loaded_objects.hpp"

using namespace yardsim::collision;
using Catch::Matchers::Contains;
using yardsim::testing::loaded;

TEST_CASE("FCL is mapped only once a collision world is made", "[fcl]") {
  // (each test case runs in its own process under ctest) => nothing of FCL at start-up
  CHECK_FALSE(loaded("libfcl"));
  CHECK_FALSE(loaded("libyardsim_fcl"));
  CHECK(fclCounts().worldsMade == 0);
  // (shapes are checked without FCL) => still nothing
  CHECK(Shape::sphere(1.0).kind == ShapeKind::kSphere);
  CHECK_FALSE(loaded("libfcl"));
  CollisionWorld world;
  CHECK(loaded("libyardsim_fcl"));
  CHECK(loaded("libfcl"));
  CHECK(fclCounts().worldsMade == 1);
  CHECK(fclCounts().worldsAlive == 1);
  // spheres of radii 1 and 0.5 m with centres 4 m apart: 2.5 m between them
  const Transform a = Transform::translation(Vector3::Zero()),
                  b = Transform::translation(Vector3(4.0, 0.0, 0.0));
  const ObjectId s1 = world.add(Shape::sphere(1.0), a), s2 = world.add(Shape::sphere(0.5), b);
  CHECK(fclCounts().objectsAlive >= 2);
  CHECK(world.distance(s1, s2).distance == Approx(2.5).epsilon(1e-9));
  CHECK_FALSE(world.intersects(s1, s2));
}

TEST_CASE("The FCL module sits beside libyardsim_collision and a missing one is named", "[fcl]") {
  const std::filesystem::path module = fclModulePath();
  CHECK(module.filename() == "libyardsim_fcl.so");
  CHECK(std::filesystem::is_regular_file(module));
  CHECK(std::filesystem::is_regular_file(module.parent_path() / "libyardsim_collision.so"));
  CHECK_THROWS_WITH(loadFclModule("/nonexistent/libyardsim_fcl.so"),
                    Contains("/nonexistent/libyardsim_fcl.so") && Contains("missing") &&
                        Contains("reinstall yardsim"));
  // a loadable library without the entry
  const std::string own = (module.parent_path() / "libyardsim_collision.so").string();
  CHECK_THROWS_WITH(loadFclModule(own), Contains(own) && Contains("yardsim_fcl_module"));
}
