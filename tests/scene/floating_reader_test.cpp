// The floating-body keys of a scene's mechanics: water, waves, current, wind, hydrostatics with a
// hull mesh found relative to the YAML file that names it (also in an included file), wind and
// current loads, damping; a free-joint box from YAML floats at its draft with the channels a
// naval architect reads; bad input refused at file:line:column with the key path.
#include "scene/floating_reader.hpp"

#include <catch2/catch.hpp>

#include "devs/simulator.hpp"
#include "forces/geometry/mesh_io.hpp"
#include "forces/geometry/primitive_meshes.hpp"
#include "forces/hydro/irregular_sea.hpp"
#include "scene/assembler.hpp"
#include "models/channels.hpp"
#include "scene/mechanical_systems.hpp"
#include "scene/resolved_listing.hpp"
#include "scene/scene_loader.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;
using Catch::Matchers::Contains;

namespace {

// a 20 x 8 x 4 box barge of 246 t: draft 1.5 m; mesh origin at mid-depth
constexpr double kM = 246000.0, kT = 1.5;

std::string sceneYaml(const std::string& extra = "", const std::string& water = "") {
  return R"(schema_version: 1
integrator: {method: rk4, dt: 0.01}
mechanics:
  water:
    density: 1025
    depth: 40
)" + water + R"(    current: {speed: 0.5, direction_deg: 90, profile: [[0, 1], [-40, 0.2]]}
  wind: {speed: 15, direction_deg: 180, profile: power_law, exponent: 0.12}
  bodies:
    barge:
      parent: world
      joint: {type: free, q0: {xyz: [0, 0, 0.5]}}
      mass: 246000
      inertia: [1.64e6, 8.53e6, 9.51e6]
  hydrostatics:
    hull: {body: barge, mesh: meshes/barge.stl}
  wind_loads:
    wind: {body: barge, point: [0, 0, 4], frontal_area: 20, lateral_area: 50, length: 20}
  current_loads:
    current: {body: barge, point: [0, 0, -1], frontal_area: 12, lateral_area: 30, length: 20,
              coefficients: {angle_deg: [0, 90, 180], cx: [-0.5, 0, 0.5], cy: [0, -1.2, 0], cmz: [0, 0, 0]}}
  damping:
    damping: {body: barge, linear: [1e4, 1e4, 1e6, 1e6, 1e7, 1e6], quadratic: [0, 0, 0, 0, 0, 0]}
)" + extra;
}

void meshes(const testing::SceneDir& dir) {
  std::filesystem::create_directories(dir.path() / "meshes");
  forces::writeStl(forces::boxMesh(dynamics::Vector3(20, 8, 4), 2, 2, 1), dir.file("meshes/barge.stl"));
}

double channel(const std::vector<models::Channel>& all, const std::string& name) {
  for (const auto& c : all)
    if (c.name == name) return c.read();
  FAIL("no channel " << name);
  return 0.0;
}

const models::Diagnostic* find(const scene::LoadResult& r, const std::string& keyPath) {
  for (const auto& d : r.diagnostics.all())
    if (d.keyPath == keyPath) return &d;
  return nullptr;
}

}  // namespace

TEST_CASE("a free box from YAML floats at the draft of its mass, with its channels") {
  testing::SceneDir dir;
  meshes(dir);
  const auto r = scene::loadScene(dir.write("s.yaml", sceneYaml()));
  INFO(r.diagnostics.report());
  REQUIRE(r.scene);
  const mechanics::MechanicsSpec& spec = r.scene->systems.at(0)->spec;
  REQUIRE(spec.hulls.size() == 1);
  CHECK(forces::solidProperties(*spec.hulls[0].mesh).volume == Approx(640.0).epsilon(1e-6));
  CHECK(spec.water.depth == 40.0);
  REQUIRE(spec.current);
  CHECK(spec.current->profile.size() == 2);
  REQUIRE(spec.wind);
  CHECK(spec.wind->exponent == 0.12);
  CHECK_THAT(scene::resolvedListing(*r.scene), Contains("barge hydrostatics:hull wind_load:wind current_load:current damping:damping"));
  auto root = scene::assemble(*r.scene);
  const auto ch = models::collectChannels(*root);
  // (keel at -1.5 m: body origin at mid-depth, z = 2 - 1.5) => already at equilibrium draft
  CHECK(channel(ch, "hull.draft") == Approx(kT));
  CHECK(channel(ch, "hull.displacement") == Approx(kM));
  CHECK(channel(ch, "hull.fz") == Approx(kM * 9.81));
  CHECK(channel(ch, "hull.gm_t") == Approx(kT / 2 + 64.0 / (12 * kT) - 2.0));
  CHECK(channel(ch, "hull.waterplane_area") == Approx(160.0));
  // (wind towards -x at 15 (4.5/10)^0.12 m/s: from ahead) => pushes aft: fx < 0
  const double u = 15.0 * std::pow(4.5 / 10.0, 0.12);
  CHECK(channel(ch, "wind.speed") == Approx(u));
  CHECK(channel(ch, "wind.fx") == Approx(-0.5 * 1.226 * u * u * 20.0));
  // (current towards +y: from -y, -90 deg; point at z = 0.5 - 1 = -0.5: factor 1 - 0.8 0.5/40;
  // the table mirrored: C_y(-90) = +1.2) => pushed to +y
  const double uc = 0.5 * (1 - 0.8 * 0.5 / 40);
  CHECK(channel(ch, "current.speed") == Approx(uc));
  CHECK(channel(ch, "current.fy") == Approx(0.5 * 1025 * uc * uc * 30 * 1.2));
  CHECK(channel(ch, "damping.fz") == 0.0);
  devs::Simulator sim(*root);
  sim.runUntil(2.0);
  CHECK(channel(ch, "hull.draft") == Approx(kT).margin(2e-3));  // the loads move it, barely
  CHECK(channel(ch, "damping.fy") < 0.0);                        // resisting the drift to +y
}

TEST_CASE("a hull in an included file: named by its path, its mesh found next to that file") {
  testing::SceneDir dir;
  std::filesystem::create_directories(dir.path() / "parts/meshes");
  forces::writeObj(forces::boxMesh(dynamics::Vector3(20, 8, 4)), dir.file("parts/meshes/box.obj"));
  dir.write("parts/pontoon.yaml", R"(schema_version: 1
mechanics:
  bodies:
    body: {parent: world, joint: {type: free}, mass: 246000, inertia: [1.64e6, 8.53e6, 9.51e6]}
  hydrostatics:
    hull: {body: body, mesh: meshes/box.obj, placement: {xyz: [0, 0, 0]}}
)");
  const auto r = scene::loadScene(dir.write("s.yaml", R"(schema_version: 1
integrator: {method: rk4, dt: 0.01}
components:
  p1: {include: parts/pontoon.yaml, placement: {xyz: [0, 0, 0.5]}}
  p2: {include: parts/pontoon.yaml, placement: {xyz: [50, 0, 0.5]}}
)"));
  INFO(r.diagnostics.report());
  REQUIRE(r.scene);
  REQUIRE(r.scene->systems.size() == 2);
  CHECK(r.scene->systems[0]->spec.hulls.at(0).name == "p1.hull");
  CHECK(r.scene->systems[1]->spec.hulls.at(0).body == "p2.body");
  auto root = scene::assemble(*r.scene);
  const auto ch = models::collectChannels(*root);
  CHECK(channel(ch, "p2.hull.draft") == Approx(kT));
}

TEST_CASE("bad floating input is refused at its line with the key path") {
  testing::SceneDir dir;
  meshes(dir);
  SECTION("a missing mesh file: the mesh key's line, the file named") {
    std::string s = sceneYaml();
    s.replace(s.find("meshes/barge.stl"), 16, "meshes/hull.stl");
    const auto r = scene::loadScene(dir.write("s.yaml", s));
    const auto* d = find(r, "mechanics.hydrostatics.hull.mesh");
    REQUIRE(d);
    CHECK(d->where.line == 16);
    CHECK(d->where.column > 1);
    CHECK_THAT(d->message, Contains("meshes/hull.stl: cannot open"));
  }
  SECTION("froude_krylov: an unknown value; none without hydrodynamics on the body") {
    std::string s = sceneYaml();
    s.replace(s.find("mesh: meshes/barge.stl}"), 23,
              "mesh: meshes/barge.stl, froude_krylov: linear}");
    auto r = scene::loadScene(dir.write("s.yaml", s));
    const auto* d = find(r, "mechanics.hydrostatics.hull.froude_krylov");
    REQUIRE(d);
    CHECK(d->where.line == 16);
    CHECK_THAT(d->message, Contains("expected nonlinear") && Contains("or none"));
    s = sceneYaml();
    s.replace(s.find("mesh: meshes/barge.stl}"), 23,
              "mesh: meshes/barge.stl, froude_krylov: none}");
    r = scene::loadScene(dir.write("s.yaml", s));
    d = find(r, "mechanics.hydrostatics.hull.froude_krylov");
    REQUIRE(d);
    CHECK(d->where.line == 16);
    CHECK_THAT(d->message, Contains("body 'barge' has no hydrodynamics block"));
    s = sceneYaml();
    s.replace(s.find("mesh: meshes/barge.stl}"), 23,
              "mesh: meshes/barge.stl, froude_krylov: nonlinear}");
    r = scene::loadScene(dir.write("s.yaml", s));
    CHECK_FALSE(find(r, "mechanics.hydrostatics.hull.froude_krylov"));
  }
  SECTION("an open mesh: the mesh file and its first offending face") {
    dir.write("meshes/barge.stl", "solid x\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n"
                                  "   vertex 0 1 0\n  endloop\n endfacet\nendsolid\n");
    const auto r = scene::loadScene(dir.write("s.yaml", sceneYaml()));
    const auto* d = find(r, "mechanics.hydrostatics.hull.mesh");
    REQUIRE(d);
    CHECK_THAT(d->message, Contains("barge.stl: face 0") && Contains("not closed"));
  }
  SECTION("water: an unknown key, a breaking wave") {
    std::string s = sceneYaml("", "    waves: [{height: 9, period: 3}]\n");
    s.replace(s.find("density: 1025"), 13, "densty: 1025");
    const auto r = scene::loadScene(dir.write("s.yaml", s));
    INFO(r.diagnostics.report());
    const auto* d = find(r, "mechanics.water.densty");
    REQUIRE(d);
    CHECK(d->where.line == 5);
    CHECK_THAT(d->message + d->hint, Contains("did you mean 'density'?"));
  }
  SECTION("a breaking wave") {
    const auto r = scene::loadScene(dir.write("s.yaml", sceneYaml("", "    waves: [{height: 9, period: 3}]\n")));
    const auto* d = find(r, "mechanics.water.waves[0]");
    REQUIRE(d);
    CHECK(d->where.line == 7);
    CHECK_THAT(d->message, Contains("breaking limit"));
  }
  SECTION("a hull scale of 1e200: refused at the scale, not at run time") {
    std::string s = sceneYaml();
    s.replace(s.find("mesh: meshes/barge.stl"), 22, "mesh: meshes/barge.stl, scale: 1e200");
    const auto r = scene::loadScene(dir.write("s.yaml", s));
    INFO(r.diagnostics.report());
    const auto* d = find(r, "mechanics.hydrostatics.hull.scale");
    REQUIRE(d);
    CHECK(d->where.line == 16);
    CHECK_THAT(d->message, Contains("from 0.001 to 1000"));
    CHECK(r.diagnostics.errorCount() == 1);
  }
  SECTION("a provider on an unknown body") {
    std::string s = sceneYaml();
    s.replace(s.find("wind: {body: barge"), 18, "wind: {body: barg");
    const auto r = scene::loadScene(dir.write("s.yaml", s));
    CHECK_THAT(r.diagnostics.report(), Contains("unknown body 'barg'") && Contains("did you mean 'barge'?"));
  }
  SECTION("a negative damping coefficient, an unknown profile") {
    std::string s = sceneYaml();
    s.replace(s.find("linear: [1e4"), 12, "linear: [-1e4");
    s.replace(s.find("power_law"), 9, "powerlaw");
    const auto r = scene::loadScene(dir.write("s.yaml", s));
    INFO(r.diagnostics.report());
    const auto* d = find(r, "mechanics.damping.damping.linear");
    REQUIRE(d);
    CHECK(d->where.line == 23);
    const auto* p = find(r, "mechanics.wind.profile");
    REQUIRE(p);
    CHECK_THAT(p->message, Contains("power_law"));
  }
  SECTION("a wind load without the scene's wind") {
    std::string s = sceneYaml();
    s.erase(s.find("  wind: {speed"), s.find('\n', s.find("  wind: {speed")) - s.find("  wind: {speed") + 1);
    const auto r = scene::loadScene(dir.write("s.yaml", s));
    CHECK_THAT(r.diagnostics.report(), Contains("wind load 'wind' needs the scene's wind"));
  }
  SECTION("water declared in an included file") {
    dir.write("part.yaml", "schema_version: 1\nmechanics:\n  water: {density: 1000}\n");
    const auto r = scene::loadScene(dir.write("s.yaml", sceneYaml("components:\n  part: {include: part.yaml}\n")));
    CHECK_THAT(r.diagnostics.report(), Contains("only the scene root declares the water"));
  }
}

TEST_CASE("an irregular sea from water waves joins the regular ones in the one sea") {
  testing::SceneDir dir;
  meshes(dir);
  const std::string sea = "    waves: [{height: 1, period: 10},\n"
                          "            {spectrum: jonswap, hs: 2.5, tp: 8, gamma: 3.3, seed: 7, spreading_s: 10, components: 50}]\n";
  const auto r = scene::loadScene(dir.write("s.yaml", sceneYaml("", sea)));
  INFO(r.diagnostics.report());
  REQUIRE(r.scene);
  const auto& waves = r.scene->systems.at(0)->spec.waves;
  REQUIRE(waves.size() == 51);
  double variance = 0;
  for (std::size_t i = 1; i < waves.size(); ++i) variance += waves[i].height * waves[i].height / 8;
  CHECK(variance == Approx(2.5 * 2.5 / 16).epsilon(1e-12));
  // (the same keys through the library) => the same components
  forces::hydro::IrregularSea s;
  s.hs = 2.5, s.tp = 8, s.gamma = 3.3, s.seed = 7, s.spreadingS = 10, s.components = 50;
  const auto expected = forces::hydro::irregularWaves(s);
  CHECK(waves[17].period == expected[16].period);
  CHECK(waves[17].direction == expected[16].direction);
  // (the hull's elevation channel) => the sea of all 51 components at the body
  auto root = scene::assemble(*r.scene);
  const auto ch = models::collectChannels(*root);
  forces::WaterProperties water;
  water.depth = 40;
  CHECK(channel(ch, "hull.wave_elevation") == Approx(forces::AiryWaves(water, waves).elevation(0, 0, 0)).margin(1e-12));
  // (one sea as a mapping) => its components alone
  const auto one = scene::loadScene(dir.write("one.yaml", sceneYaml("", "    waves: {spectrum: pm, hs: 1, tp: 6}\n")));
  INFO(one.diagnostics.report());
  REQUIRE(one.scene);
  CHECK(one.scene->systems.at(0)->spec.waves.size() == 200);
}

TEST_CASE("bad irregular seas are refused at their keys") {
  testing::SceneDir dir;
  meshes(dir);
  auto load = [&](const std::string& waves) { return scene::loadScene(dir.write("s.yaml", sceneYaml("", waves))); };
  SECTION("an unknown spectrum") {
    const auto r = load("    waves: [{spectrum: jonswapp, hs: 2, tp: 8}]\n");
    const auto* d = find(r, "mechanics.water.waves[0].spectrum");
    REQUIRE(d);
    CHECK(d->where.line == 7);
    CHECK_THAT(d->message + d->hint, Contains("did you mean 'jonswap'?"));
  }
  SECTION("a negative Hs and a fractional number of components") {
    const auto r = load("    waves:\n      spectrum: jonswap\n      hs: -2\n      tp: 8\n      components: 20.5\n");
    INFO(r.diagnostics.report());
    const auto* hs = find(r, "mechanics.water.waves.hs");
    REQUIRE(hs);
    CHECK(hs->where.line == 9);
    CHECK_THAT(hs->message, Contains("> 0"));
    const auto* n = find(r, "mechanics.water.waves.components");
    REQUIRE(n);
    CHECK(n->where.line == 11);
    CHECK_THAT(n->message, Contains("whole number"));
  }
  SECTION("gamma of a Pierson-Moskowitz sea, a breaking sea, a missing tp") {
    const auto r = load("    waves: [{spectrum: pm, hs: 2, tp: 8, gamma: 2}, {spectrum: jonswap, hs: 12, tp: 3}, {spectrum: pm, hs: 1}]\n");
    INFO(r.diagnostics.report());
    CHECK(find(r, "mechanics.water.waves[0].gamma"));
    const auto* b = find(r, "mechanics.water.waves[1]");
    REQUIRE(b);
    CHECK_THAT(b->message, Contains("breaking limit"));
    const auto* t = find(r, "mechanics.water.waves[2].tp");
    REQUIRE(t);
    CHECK_THAT(t->message, Contains("missing required key"));
  }
}
