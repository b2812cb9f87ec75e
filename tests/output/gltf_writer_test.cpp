#include "output/gltf_writer.hpp"

#include <catch2/catch.hpp>
#include <cmath>

#include "scene/assembler.hpp"
#include "run/runner.hpp"
#include "scene/scene_loader.hpp"
#include "support/glb_file.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;

namespace {
// (glb, node, path, t) => the channel's value at a sample time t (exact key, no interpolation)
std::vector<float> at(const testing::GlbFile& g, int node, const std::string& path, double t) {
  const auto [times, values] = g.channel(node, path);
  const std::size_t n = values.size() / times.size();
  for (std::size_t k = 0; k < times.size(); ++k)
    if (std::abs(times[k] - t) < 1e-6) return {values.begin() + k * n, values.begin() + (k + 1) * n};
  throw std::runtime_error("no key at t = " + std::to_string(t));
}
}  // namespace

TEST_CASE("replay.glb of a run reads back the known pose at a known time") {
  // A body on a vertical revolute axis spun at 0.5 rad/s (gravity along the axis: no torque, so
  // q = 0.5 t) and a free body falling from rest, rolled by 30 deg.
  testing::SceneDir dir;
  const auto file = dir.write("s.yaml", R"(schema_version: 1
components:
  m:
    type: multibody
    params:
      dt: 0.01
      bodies:
        spinner:
          parent: world
          joint: {type: revolute, axis: [0, 0, 1], v0: 0.5}
          placement: {xyz: [3, 0, 1]}
          mass: 2
          inertia: [1, 1, 1]
          geometry: {cylinder: {radius: 0.5, length: 0.2}}
        faller:
          parent: world
          joint: {type: free, q0: {xyz: [1, 2, 10], rpy_deg: [30, 0, 0]}}
          mass: 1
          inertia: [0.1, 0.1, 0.1]
record: {interval: 0.1, channels: ['*']}
until: 1
)");
  auto scene = scene::loadSceneOrThrow(file);
  auto root = scene::assemble(*scene);
  run::runScene(*scene, *root, {dir.path() / "out", 1.0, {}, {}, 0.1, 2000});
  const testing::GlbFile g((dir.path() / "out/replay.glb").string());
  const int spinner = g.bodyNode("m.spinner"), faller = g.bodyNode("m.faller");
  REQUIRE(spinner > 0);
  REQUIRE(faller > 0);
  // rotation about z by 0.5 t: (x, y, z, w) = (0, 0, sin(t / 4), cos(t / 4)); w last
  const auto r = at(g, spinner, "rotation", 1.0);
  CHECK(r[0] == Approx(0.0).margin(1e-6));
  CHECK(r[1] == Approx(0.0).margin(1e-6));
  CHECK(r[2] == Approx(std::sin(0.25)).margin(1e-6));
  CHECK(r[3] == Approx(std::cos(0.25)).margin(1e-6));
  const auto p = at(g, spinner, "translation", 1.0);
  CHECK(p == std::vector<float>{3.0f, 0.0f, 1.0f});
  // free fall from rest: z = 10 - g t^2 / 2 (RK4 is exact for a constant acceleration); roll 30
  // deg kept: (sin 15 deg, 0, 0, cos 15 deg)
  const auto z = at(g, faller, "translation", 1.0);
  CHECK(z[0] == Approx(1.0).margin(1e-6));
  CHECK(z[1] == Approx(2.0).margin(1e-6));
  CHECK(z[2] == Approx(10.0 - 9.81 / 2).margin(1e-5));
  const auto q = at(g, faller, "rotation", 0.5);
  CHECK(q[0] == Approx(std::sin(M_PI / 12)).margin(1e-6));
  CHECK(q[1] == Approx(0.0).margin(1e-6));
  CHECK(q[2] == Approx(0.0).margin(1e-6));
  CHECK(q[3] == Approx(std::cos(M_PI / 12)).margin(1e-6));
}

TEST_CASE("the GLB container is well formed: header, 4-byte aligned chunks and views, min and max") {
  models::Replay replay;
  replay.times = {0.0f, 0.5f, 1.0f};
  models::ReplayBody b;
  b.name = "crane.block";
  b.shape = mechanics::MechanicsSpec::Visual::Shape::Box;
  b.size = {2.0, 4.0, 6.0};
  b.X_BG = dynamics::Transform::translation({0.0, 0.0, -0.5});
  b.translation = {{0, 0, 0}, {1, 2, 3}, {-1, 5, 0}};
  b.rotation = {{0, 0, 0, 1}, {0, 0, 0, 1}, {0, 0, 0, 1}};
  replay.bodies = {b, b};
  replay.bodies[1].name = "\"quoted\" name";
  replay.ropes.push_back({"hoist", {{-1, {0, 0, 20}}, {0, {0, 0, 3}}}});
  testing::SceneDir dir;
  output::writeGlb(replay, dir.path() / "r.glb");
  const testing::GlbFile g((dir.path() / "r.glb").string());
  CHECK(g.magic == 0x46546C67u);
  CHECK(g.version == 2);
  CHECK(g.length == g.bytes.size());
  CHECK(g.jsonType == 0x4E4F534Au);
  CHECK(g.binType == 0x004E4942u);
  CHECK(g.jsonLength % 4 == 0);
  CHECK(g.binLength % 4 == 0);
  CHECK(20 + g.jsonLength + 8 + g.binLength == g.bytes.size());
  CHECK(g.json["buffers"][0]["byteLength"].as<std::uint32_t>() == g.binLength);
  for (const auto& v : g.json["bufferViews"]) CHECK(v["byteOffset"].as<int>() % 4 == 0);
  // (every accessor) => min and max equal to the extremes of its data
  for (std::size_t a = 0; a < g.json["accessors"].size(); ++a) {
    const YAML::Node acc = g.json["accessors"][a];
    REQUIRE(acc["min"]);
    REQUIRE(acc["max"]);
    const std::size_t n = acc["min"].size();
    std::vector<double> lo(n, 1e300), hi(n, -1e300);
    if (acc["componentType"].as<int>() == 5126) {
      const auto f = g.floats(static_cast<int>(a));
      for (std::size_t i = 0; i < f.size(); ++i) {
        lo[i % n] = std::min(lo[i % n], double{f[i]});
        hi[i % n] = std::max(hi[i % n], double{f[i]});
      }
      for (std::size_t k = 0; k < n; ++k) {
        CHECK(acc["min"][k].as<double>() == lo[k]);
        CHECK(acc["max"][k].as<double>() == hi[k]);
      }
    }
  }
  // (box 2 x 4 x 6 centred 0.5 m below the body origin) => POSITION bounds
  const int pos = g.json["meshes"][0]["primitives"][0]["attributes"]["POSITION"].as<int>();
  CHECK(g.json["accessors"][pos]["min"].as<std::vector<double>>() == std::vector<double>{-1, -2, -3.5});
  CHECK(g.json["accessors"][pos]["max"].as<std::vector<double>>() == std::vector<double>{1, 2, 2.5});
  // the input (time) accessor of the animation and the translations as given
  const auto [times, values] = g.channel(1, "translation");
  CHECK(times == replay.times);
  CHECK(values == std::vector<float>{0, 0, 0, 1, 2, 3, -1, 5, 0});
  CHECK(g.bodyNode("\"quoted\" name") == 2);
  // the root turns z-up into y-up: -90 deg about x
  CHECK(g.json["nodes"][0]["rotation"][0].as<double>() == Approx(-std::sqrt(0.5)));
  CHECK(g.json["nodes"][0]["rotation"][3].as<double>() == Approx(std::sqrt(0.5)));
  const YAML::Node rope = g.json["scenes"][0]["extras"]["yardsim_ropes"][0];
  CHECK(rope["name"].as<std::string>() == "hoist");
  CHECK(rope["points"][1]["node"].as<int>() == 0);
  CHECK(rope["points"][0]["p"][2].as<double>() == 20.0);
}

TEST_CASE("a replay whose bodies miss poses is refused") {
  models::Replay replay;
  replay.times = {0.0f, 1.0f};
  replay.bodies.resize(1);
  replay.bodies[0].name = "b";
  CHECK_THROWS_WITH(output::glbBytes(replay), Catch::Contains("'b' has 0 poses for 2 frames"));
}

TEST_CASE("a mesh geometry (OBJ, relative to the scene file) becomes the body's glTF mesh in the body frame") {
  testing::SceneDir dir;
  // a tetrahedron spanning [0, 2] x [0, 3] x [0, 4] in the body frame
  dir.write("meshes/tet.obj", "v 0 0 0\nv 2 0 0\nv 0 3 0\nv 0 0 4\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  const auto file = dir.write("s.yaml", R"(schema_version: 1
components:
  m:
    type: multibody
    params:
      dt: 0.01
      bodies:
        tet: {parent: world, joint: {type: fixed}, mass: 1, inertia: [1, 1, 1], geometry: {mesh: meshes/tet.obj}}
record: {interval: 0.1}
until: 0.2
)");
  auto scene = scene::loadSceneOrThrow(file);
  auto root = scene::assemble(*scene);
  run::runScene(*scene, *root, {dir.path() / "out", 0.2, {}, {}, 0.1, 2000});
  const testing::GlbFile g((dir.path() / "out/replay.glb").string());
  const int pos = g.json["meshes"][0]["primitives"][0]["attributes"]["POSITION"].as<int>();
  CHECK(g.json["accessors"][pos]["min"].as<std::vector<double>>() == std::vector<double>{0, 0, 0});
  CHECK(g.json["accessors"][pos]["max"].as<std::vector<double>>() == std::vector<double>{2, 3, 4});
  CHECK(g.json["accessors"][pos]["count"].as<int>() == 12);  // 4 triangles, flat normals

  const auto bad = dir.write("bad.yaml", R"(schema_version: 1
components:
  m:
    type: multibody
    params:
      dt: 0.01
      bodies:
        tet: {parent: world, joint: {type: fixed}, mass: 1, inertia: [1, 1, 1], geometry: {mesh: nowhere.obj}}
)");
  const auto r = scene::loadScene(bad);
  REQUIRE(r.diagnostics.errorCount() == 1);
  CHECK(r.diagnostics.all()[0].keyPath == "components.m.params.bodies.tet.geometry.mesh");
  CHECK_THAT(r.diagnostics.all()[0].message, Catch::Contains("nowhere.obj"));
}
