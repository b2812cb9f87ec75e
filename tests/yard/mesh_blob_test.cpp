// A mesh through a blob and back, bit for bit; a foreign or truncated blob refused.
#include <catch2/catch.hpp>

#include "forces/geometry/primitive_meshes.hpp"
#include "yard/database.hpp"
#include "yard/mesh_blob.hpp"

using namespace yardsim::yard;
using Catch::Matchers::Contains;

TEST_CASE("a mesh survives the blob exactly") {
  const auto hull = yardsim::forces::cylinderMesh(3.0, -4.0, 2.0, 40, 3);
  const auto blob = meshToBlob(hull);
  CHECK(blob.size() == 12 + 24 * hull.vertices.size() + 12 * hull.triangles.size());
  const auto back = meshFromBlob(blob, "db:hull");
  CHECK(back.vertices == hull.vertices);
  CHECK(back.triangles == hull.triangles);
  CHECK(back.source == "db:hull");
}

TEST_CASE("a blob that is not a mesh is refused") {
  auto blob = meshToBlob(yardsim::forces::cylinderMesh(1.0, -1.0, 1.0, 8, 1));
  CHECK_THROWS_WITH(meshFromBlob({'a', 'b'}, "x"), Contains("not a yardsim mesh"));
  auto cut = blob;
  cut.pop_back();
  CHECK_THROWS_WITH(meshFromBlob(cut, "x"), Contains("truncated"));
  blob[blob.size() - 4] = 0xff;  // the last index far out of range
  CHECK_THROWS_WITH(meshFromBlob(blob, "x"), Contains("bad index"));
}
