// The multibody model's lines in the 3D replay (models/multibody/multibody_replay.cpp), read back
// from replay.glb: a catenary mooring line is drawn through markers that lie, at every recorded
// frame, on an independent solve of its catenary (forces/lines/catenary.hpp) to where the
// fairlead body is in that frame; a lumped mooring line and a lumped rope over a sheave through
// their nodes (the node bodies, in order, and the sheave point).
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "forces/lines/catenary.hpp"
#include "run/runner.hpp"
#include "scene/assembler.hpp"
#include "scene/scene_loader.hpp"
#include "support/glb_file.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;

namespace {

// (the chain: 450 m, EA 1e9 N, 1000 N/m in water; the anchor on the bed 400 m west, 100 m down)
const forces::CatenaryParameters kChain{450.0, 1.0e9, 1000.0, true, 0.0};

// a buoy surging at 0.5 m/s between a catenary line (west) and a lumped line (north); a 2 t block
// hanging from a fixed anchor over a sheave by a lumped rope of 7 segments
const char* const kScene = R"(schema_version: 1
integrator: {method: rk4, dt: 0.005}
mechanics:
  gravity: [0, 0, -9.81]
  bodies:
    buoy: {parent: world, joint: {type: prismatic, axis: [1, 0, 0], v0: 0.5}, mass: 1.0e5, inertia: [1, 1, 1]}
    carrier: {parent: world, joint: {type: fixed}, placement: {xyz: [0, 50, 30]}, mass: 500, inertia: [1, 1, 1]}
    anchor: {parent: world, joint: {type: fixed}, placement: {xyz: [-3, 50, 12]}, mass: 1000, inertia: [1, 1, 1]}
    block: {parent: world, joint: {type: prismatic, axis: [0, 0, 1], q0: 12}, placement: {xyz: [4, 50, 0]}, mass: 2000, inertia: [1, 1, 1]}
  mooring:
    west: {anchor: [-400, 0, -100], fairlead: {body: buoy}, length: 450, EA: 1.0e9, weight: 1000}
    north: {model: lumped, anchor: [0, 400, -100], fairlead: {body: buoy}, length: 450, EA: 1e9,
            mass: 130, diameter: 0.12, segments: 8}
  ropes:
    hoist: {model: lumped, path: [{body: anchor}, {body: carrier, point: [0, 0, 0.5]}, {body: block}],
            L0: 36, segments: 7, EA: 2.0e6, mass_per_length: 10, diameter: 0.04}
record: {interval: 0.1, channels: ["buoy.x"]}
until: 1
)";

// (glb, rope name) => its entry in the scene's extras
YAML::Node rope(const testing::GlbFile& g, const std::string& name) {
  for (const auto& r : g.json["scenes"][0]["extras"]["yardsim_ropes"])
    if (r["name"].as<std::string>() == name) return r;
  FAIL("no rope " << name);
  return {};
}

// (glb, a rope's point) => the name of the body it is on ("world" for -1) and its point
std::pair<std::string, std::vector<double>> on(const testing::GlbFile& g, const YAML::Node& p) {
  const int body = p["node"].as<int>();
  return {body < 0 ? "world" : g.json["nodes"][body + 1]["name"].as<std::string>(),
          p["p"].as<std::vector<double>>()};
}

const std::vector<double> kOrigin{0.0, 0.0, 0.0};

// (glb, mooring line's name, its number of points, its anchor) => the line, checked to run from
// the anchor in the world to the buoy's origin
YAML::Node mooringLine(const testing::GlbFile& g, const std::string& name, std::size_t points,
                       const std::vector<double>& anchor) {
  const YAML::Node r = rope(g, name);
  REQUIRE(r["points"].size() == points);
  CHECK(on(g, r["points"][0]) == std::pair{std::string("world"), anchor});
  CHECK(on(g, r["points"][points - 1]) == std::pair{std::string("buoy"), kOrigin});
  return r;
}

// (folder, until) => the scene run there, its replay.glb read back
testing::GlbFile replayOf(const testing::SceneDir& dir, double until) {
  auto scene = scene::loadSceneOrThrow(dir.write("s.yaml", kScene));
  auto root = scene::assemble(*scene);
  run::runScene(*scene, *root, {dir.path() / "out", until, {}, {}, 0.1});
  return testing::GlbFile((dir.path() / "out/replay.glb").string());
}

}  // namespace

TEST_CASE("replay: a catenary line is drawn through its profile at every frame") {
  testing::SceneDir dir;
  const testing::GlbFile g = replayOf(dir, 1.0);
  const YAML::Node west = mooringLine(g, "west", 21, {-400.0, 0.0, -100.0});
  const int buoy = g.bodyNode("buoy");
  REQUIRE(buoy > 0);
  const auto [times, fairlead] = g.channel(buoy, "translation");
  REQUIRE(times.size() == 11);
  for (int k = 1; k < 20; ++k) {
    // (marker k) => a node without a mesh or rotation, on the catenary at s = k L / 20
    const int node = west["points"][k]["node"].as<int>() + 1;
    CHECK(on(g, west["points"][k]).second == kOrigin);
    CHECK(!g.json["nodes"][node]["mesh"]);
    CHECK_THROWS(g.channel(node, "rotation"));
    const auto [t, p] = g.channel(node, "translation");
    REQUIRE(t.size() == times.size());
    for (std::size_t f = 0; f < times.size(); ++f) {
      const double xf = fairlead[3 * f] + 400.0, zf = fairlead[3 * f + 2] + 100.0;
      const auto c = forces::solveCatenary(kChain, xf, zf);
      REQUIRE(c.status == forces::CatenaryStatus::Converged);
      const auto x = forces::catenaryPoint(kChain, c, xf, 450.0 * k / 20);
      INFO("marker " << k << " at t = " << times[f]);
      CHECK(p[3 * f] == Approx(-400.0 + x.x).margin(1e-3));
      CHECK(p[3 * f + 1] == Approx(0.0).margin(1e-3));
      CHECK(p[3 * f + 2] == Approx(-100.0 + x.z).margin(1e-3));
    }
  }
  // (the buoy moved, held back by the lines) => the profile with it
  CHECK(fairlead[3 * 10] > fairlead[0] + 0.1);
}

TEST_CASE("replay: lumped lines and ropes are drawn through their nodes") {
  testing::SceneDir dir;
  const testing::GlbFile g = replayOf(dir, 0.2);
  // (mooring line of 8 segments) => the anchor, its nodes 1 .. 7 at their origins, the buoy
  const YAML::Node north = mooringLine(g, "north", 9, {0.0, 400.0, -100.0});
  for (int i = 1; i < 8; ++i)
    CHECK(on(g, north["points"][i]) == std::pair{"north.node" + std::to_string(i), kOrigin});
  // (rope over a sheave: 3 segments in span A, one over the sheave, 3 in span B) => the anchor,
  // span A's nodes to p, the sheave point, q and span B's nodes, the block
  const YAML::Node hoist = rope(g, "hoist");
  const std::vector<std::string> bodies{"anchor",        "hoist.a.node1", "hoist.a.node2",
                                        "hoist.a.node3", "carrier",       "hoist.b.node0",
                                        "hoist.b.node1", "hoist.b.node2", "block"};
  REQUIRE(hoist["points"].size() == bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i)
    CHECK(on(g, hoist["points"][i]) ==
          std::pair{bodies[i], i == 4 ? std::vector{0.0, 0.0, 0.5} : kOrigin});
}
