// OBJ and STL (binary and ASCII) round trips through real files, hand-written OBJ forms, and
// the errors naming the file and line.
#include <catch2/catch.hpp>

#include <filesystem>

#include "forces/geometry/mesh_io.hpp"
#include "forces/geometry/primitive_meshes.hpp"
#include "support/scene_files.hpp"

using namespace yardsim::forces;
using yardsim::dynamics::Vector3;
using yardsim::testing::SceneDir;
using Catch::Matchers::Contains;

TEST_CASE("a hull written as OBJ, binary STL and ASCII STL reads back closed with its volume") {
  SceneDir dir;
  const TriangleMesh hull = cylinderMesh(3.0, -4.0, 2.0, 40, 3);
  const double V = solidProperties(hull).volume;
  writeObj(hull, dir.file("hull.obj"));
  writeStl(hull, dir.file("hull.stl"), true);
  writeStl(hull, dir.file("hull_ascii.STL"), false);
  for (const char* name : {"hull.obj", "hull.stl", "hull_ascii.STL"}) {
    INFO(name);
    const TriangleMesh m = readClosedMesh(dir.file(name));
    CHECK(m.source == dir.file(name));
    CHECK(m.triangles.size() == hull.triangles.size());
    CHECK(m.vertices.size() == hull.vertices.size());  // STL corners welded back
    CHECK(solidProperties(m).volume == Approx(V).epsilon(1e-6));  // STL: float32 coordinates
  }
  CHECK(solidProperties(readObj(dir.file("hull.obj"))).volume == Approx(V).epsilon(1e-14));
}

TEST_CASE("OBJ quads, v/vt/vn corners and negative indices") {
  SceneDir dir;
  // a unit cube: 8 vertices, 6 quads in mixed corner forms (CCW from outside)
  dir.write("cube.obj", R"(# cube
o cube
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
vn 0 0 1
vt 0 0
f 1 4 3 2
f 5/1 6/1 7/1 8/1
f 1//1 2//1 6//1 5//1
f -7/1/1 -6/1/1 -2/1/1 -3/1/1
f 3 4 8 7
f 4 1 5 8
)");
  const TriangleMesh m = readClosedMesh(dir.file("cube.obj"));
  CHECK(m.triangles.size() == 12u);
  CHECK(solidProperties(m).volume == Approx(1.0).epsilon(1e-15));
  CHECK((solidProperties(m).centroid - Vector3(0.5, 0.5, 0.5)).norm() < 1e-15);
}

TEST_CASE("reader errors name the file and the line or face") {
  SceneDir dir;
  dir.write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 x\n");
  CHECK_THROWS_WITH(readMesh(dir.file("bad.obj")), Contains("bad.obj:3: expected three finite coordinates"));
  dir.write("idx.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
  CHECK_THROWS_WITH(readMesh(dir.file("idx.obj")), Contains("idx.obj:4: face corner 4"));
  dir.write("open.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  CHECK_NOTHROW(readMesh(dir.file("open.obj")));
  CHECK_THROWS_WITH(readClosedMesh(dir.file("open.obj")), Contains("open.obj: face 0") && Contains("not closed"));
  dir.write("hull.ply", "ply\n");
  CHECK_THROWS_WITH(readMesh(dir.file("hull.ply")), Contains("unknown mesh format '.ply'"));
  CHECK_THROWS_WITH(readMesh(dir.file("missing.stl")), Contains("missing.stl: cannot open"));
  dir.write("junk.stl", "solid x\n  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n  endfacet\n");
  CHECK_THROWS_WITH(readMesh(dir.file("junk.stl")), Contains("junk.stl:5: a facet with 1 vertices"));
  dir.write("text.stl", "hello world\n");
  CHECK_THROWS_WITH(readMesh(dir.file("text.stl")), Contains("text.stl:1: unexpected 'hello'"));
}

TEST_CASE(
    "a mesh path that is a device or a folder or over the size limit is refused before reading") {
  SceneDir dir;
  // (a symlink to /dev/zero named .stl) => refused, not read for ever
  std::filesystem::create_symlink("/dev/zero", dir.path() / "zero.stl");
  CHECK_THROWS_WITH(readMesh(dir.file("zero.stl")), Contains("zero.stl: not a regular file"));
  std::filesystem::create_directories(dir.path() / "folder.obj");
  CHECK_THROWS_WITH(readMesh(dir.file("folder.obj")), Contains("folder.obj: not a regular file"));
  // (a sparse file one byte over the limit) => refused with the sizes, before it is read
  dir.write("huge.obj", "v 0 0 0\n");
  std::filesystem::resize_file(dir.path() / "huge.obj", kMaxMeshFileBytes + 1);
  CHECK_THROWS_WITH(readMesh(dir.file("huge.obj")),
                    Contains("huge.obj: 268435457 bytes") && Contains("256 MiB"));
}
