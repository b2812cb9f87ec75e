// The `hydrodynamics:` block of scene/floating_reader.cpp: method impulse_response with a response
// computed by a solver registered at run time (as part A's time-domain solver will be), written
// to the cache by its key and read from there the second time (the solver not called again), its
// A_inf put on the body's left-hand side, the provider running in the scene on the one sea; a
// response given as a file; rankine_td refused without its settings, the solver's two paths
// (marched and convolved) agreeing on one scene, and a registered method built; a registered check's problem, a damaged cache file and wrong keys refused at their lines.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "devs/simulator.hpp"
#include "forces/geometry/mesh_io.hpp"
#include "forces/geometry/primitive_meshes.hpp"
#include "forces/hydro/hydrodynamics_methods.hpp"
#include "forces/hydro/impulse_response_cache.hpp"
#include "forces/hydro/impulse_response_force.hpp"
#include "models/channels.hpp"
#include "scene/assembler.hpp"
#include "scene/mechanical_systems.hpp"
#include "scene/scene_loader.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;
using namespace yardsim::forces::hydro;
using Catch::Matchers::Contains;

namespace {

int solves = 0;

// (request) => heave radiation kappa e^(-t) cos(2 t) over the request's memory, A_inf 5e4 kg in
// heave, an excitation pulse per heading
ImpulseResponse testSolve(const HydrodynamicsRequest& q) {
  ++solves;
  ImpulseResponse ir;
  ir.dt = q.dt;
  ir.aInf(2, 2) = 5e4 * q.settings.at("scale");
  for (int k = 0; k * q.dt < q.memory; ++k) {
    ImpulseResponse::Matrix6 K = ImpulseResponse::Matrix6::Zero();
    K(2, 2) = 1e5 * std::exp(-k * q.dt) * std::cos(2 * k * q.dt);
    ir.radiation.push_back(K);
  }
  ir.headings = q.headings;
  ir.excitationStart = -2.0;
  for (std::size_t b = 0; b < q.headings.size(); ++b) {
    ir.excitation.emplace_back();
    for (int k = 0; k * q.dt < 4.0; ++k) {
      ImpulseResponse::Vector6 h = ImpulseResponse::Vector6::Zero();
      h[2] = 1e5 * std::exp(-std::pow(-2.0 + k * q.dt, 2));
      ir.excitation.back().push_back(h);
    }
  }
  return ir;
}

std::string sceneYaml(const std::string& hydro) {
  return R"(schema_version: 1
integrator: {method: rk4, dt: 0.02}
mechanics:
  water:
    density: 1025
    waves: [{height: 1, period: 8}]
  bodies:
    barge:
      parent: world
      joint: {type: free, q0: {xyz: [0, 0, 0.5]}}
      mass: 246000
      inertia: [1.64e6, 8.53e6, 9.51e6]
  hydrostatics:
    hull: {body: barge, mesh: meshes/barge.stl}
  hydrodynamics:
)" + hydro;
}

void meshes(const testing::SceneDir& dir) {
  std::filesystem::create_directories(dir.path() / "meshes");
  forces::writeStl(forces::boxMesh(dynamics::Vector3(20, 8, 4), 2, 2, 1),
                   dir.file("meshes/barge.stl"));
}

const models::Diagnostic* find(const scene::LoadResult& r, const std::string& keyPath) {
  for (const auto& d : r.diagnostics.all())
    if (d.keyPath == keyPath) return &d;
  return nullptr;
}

double channel(const std::vector<models::Channel>& all, const std::string& name) {
  for (const auto& c : all)
    if (c.name == name) return c.read();
  FAIL("no channel " << name);
  return 0.0;
}

const std::string kEntry =
    "    hd: {body: barge, method: impulse_response, hull: meshes/barge.stl, solver: test_solver,\n"
    "         headings_deg: [0, 90], dt: 0.05, memory: 10, cache: cache, settings: {scale: 2}}\n";

}  // namespace

TEST_CASE("rankine_td without its free-surface settings is refused at its entry") {
  testing::SceneDir dir;
  meshes(dir);
  const auto r = scene::loadScene(dir.write(
      "s.yaml", sceneYaml("    hd: {body: barge, method: rankine_td, hull: meshes/barge.stl}\n")));
  const auto* d = find(r, "mechanics.hydrodynamics.hd");
  REQUIRE(d);
  CHECK(d->where.line == 16);
  CHECK_THAT(d->message, Contains("missing setting 'truncation_radius'"));
}

namespace {
// (hydrodynamics entry or "") => the box barge released 0.3 m above its draft in calm water, its
// heave z(t) sampled every 0.25 s over 16 s
std::vector<double> heaveDecay(const testing::SceneDir& dir, const std::string& entry) {
  const std::string yaml = R"(schema_version: 1
integrator: {method: rk4, dt: 0.05}
mechanics:
  water: {density: 1025}
  bodies:
    barge:
      parent: world
      joint: {type: free, q0: {xyz: [0, 0, 0.8]}}
      mass: 246000
      inertia: [1.64e6, 8.53e6, 9.51e6]
  hydrostatics:
    hull: {body: barge, mesh: meshes/barge.stl}
)" + (entry.empty() ? std::string() : "  hydrodynamics:\n" + entry);
  const auto r = scene::loadScene(dir.write("decay.yaml", yaml));
  INFO(r.diagnostics.report());
  REQUIRE(r.scene);
  auto root = scene::assemble(*r.scene);
  const auto ch = models::collectChannels(*root);
  devs::Simulator sim(*root);
  std::vector<double> z;
  for (double t = 0.0; t <= 16.0 + 1e-9; t += 0.25) {
    sim.runUntil(t);
    z.push_back(channel(ch, "barge.z") - 0.5);
  }
  return z;
}
}  // namespace

TEST_CASE("rankine_td marched with the run and its impulse responses convolved agree in a scene") {
  testing::SceneDir dir;
  meshes(dir);
  // (one free surface for both paths: 8 panels around, out to 60 m, a 25 m damping zone)
  const std::string settings =
      "settings: {truncation_radius: 60, first_spacing: 1.5, max_spacing: 4, longest_period: 4}";
  const auto td = heaveDecay(
      dir, "    hd: {body: barge, method: rankine_td, hull: meshes/barge.stl, dt: 0.05, " + settings + "}\n");
  const auto ir = heaveDecay(dir, "    hd: {body: barge, method: impulse_response, hull: meshes/barge.stl, "
                                  "solver: rankine_td, dt: 0.05, memory: 16, cache: cache, excitation: false, " +
                                      settings + "}\n");
  const auto none = heaveDecay(dir, "");
  REQUIRE(td.size() == ir.size());
  // (same radiation, two paths) => the same heave history within a few per cent of the release
  double worst = 0.0, tdLate = 0.0, noneLate = 0.0;
  for (std::size_t k = 0; k < td.size(); ++k) {
    worst = std::max(worst, std::abs(td[k] - ir[k]));
    if (k >= 32) {  // (after 8 s)
      tdLate = std::max(tdLate, std::abs(td[k]));
      noneLate = std::max(noneLate, std::abs(none[k]));
    }
  }
  INFO("largest difference " << worst << " m of a 0.3 m release; after 8 s: " << tdLate
                             << " m with radiation, " << noneLate << " m without");
  CHECK(std::abs(td[0] - 0.3) < 1e-9);
  CHECK(worst < 0.03 * 0.3);
  // (radiation damping) => the heave decays; without it, it does not
  CHECK(tdLate < 0.5 * 0.3);
  CHECK(noneLate > 0.8 * 0.3);
}

TEST_CASE("an impulse response solved once then read from the cache drives the body") {
  registerImpulseResponseSolver({"test_solver", testSolve, {}});
  testing::SceneDir dir;
  meshes(dir);
  solves = 0;
  const auto path = dir.write("s.yaml", sceneYaml(kEntry));
  const auto r = scene::loadScene(path);
  INFO(r.diagnostics.report());
  REQUIRE(r.scene);
  CHECK(solves == 1);
  // (one file in the cache folder next to the scene, named by the key)
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(dir.path() / "cache"))
    files.push_back(e.path());
  REQUIRE(files.size() == 1);
  CHECK(files[0].extension() == ".ysir");
  CHECK(files[0].stem().string().rfind("test_solver-", 0) == 0);
  const auto& spec = r.scene->systems.at(0)->spec;
  REQUIRE(spec.hydrodynamics.size() == 1);
  REQUIRE(spec.bodies.at(0).addedMass);
  CHECK((*spec.bodies[0].addedMass)(2, 2) == 1e5);
  // (the same scene again) => from the cache, the solver not called; another setting: solved again
  const auto again = scene::loadScene(path);
  REQUIRE(again.scene);
  CHECK(solves == 1);
  std::string other = kEntry;
  other.replace(other.find("scale: 2"), 8, "scale: 3");
  REQUIRE(scene::loadScene(dir.write("s2.yaml", sceneYaml(other))).scene);
  CHECK(solves == 2);
  // (run) => the provider's power channel: the waves do work on the barge through it
  auto root = scene::assemble(*r.scene);
  const auto ch = models::collectChannels(*root);
  devs::Simulator sim(*root);
  sim.runUntil(3.0);
  CHECK(channel(ch, "hd.power") != 0.0);
  CHECK(std::isfinite(channel(ch, "hd.power")));
}

TEST_CASE("a response given as a file") {
  testing::SceneDir dir;
  meshes(dir);
  HydrodynamicsRequest q;
  q.settings["scale"] = 1;
  q.headings = {0.0};
  ImpulseResponse ir = testSolve(q);
  ir.key = "given";
  writeImpulseResponse(ir, dir.path() / "barge.ysir");
  const auto r = scene::loadScene(dir.write(
      "s.yaml",
      sceneYaml("    hd: {body: barge, method: impulse_response, response: barge.ysir}\n")));
  INFO(r.diagnostics.report());
  REQUIRE(r.scene);
  CHECK((*r.scene->systems.at(0)->spec.bodies.at(0).addedMass)(2, 2) == 5e4);
}

TEST_CASE("froude_krylov none is refused with a response of diffraction only") {
  // (a hull clipped at still water) => its waves' force must come whole from the response: one
  // that records diffraction only is refused at the hull's froude_krylov key, one with
  // Froude-Krylov is taken; excitation: false in waves is refused too
  testing::SceneDir dir;
  meshes(dir);
  HydrodynamicsRequest q;
  q.settings["scale"] = 1;
  q.headings = {0.0};
  ImpulseResponse ir = testSolve(q);
  ir.key = "given";
  ir.froudeKrylov = false;
  writeImpulseResponse(ir, dir.path() / "diffraction.ysir");
  ir.froudeKrylov = true;
  writeImpulseResponse(ir, dir.path() / "both.ysir");
  auto load = [&](const std::string& file, const std::string& more) {
    std::string s = sceneYaml("    hd: {body: barge, method: impulse_response, response: " + file + more + "}\n");
    s.replace(s.find("mesh: meshes/barge.stl}"), 23, "mesh: meshes/barge.stl, froude_krylov: none}");
    return scene::loadScene(dir.write("s.yaml", s));
  };
  auto r = load("diffraction.ysir", "");
  const auto* d = find(r, "mechanics.hydrostatics.hull.froude_krylov");
  REQUIRE(d);
  CHECK(d->where.line == 14);
  CHECK(d->where.column > 1);
  CHECK_THAT(d->message, Contains("the response of 'hd' is diffraction only") &&
                             Contains("expected an excitation that includes Froude-Krylov"));
  r = load("both.ysir", "");
  INFO(r.diagnostics.report());
  CHECK(r.scene);
  r = load("both.ysir", ", excitation: false");
  d = find(r, "mechanics.hydrostatics.hull.froude_krylov");
  REQUIRE(d);
  CHECK_THAT(d->message, Contains("'hd' has excitation: false in waves"));
}

TEST_CASE("bad hydrodynamics input is refused at its key") {
  registerImpulseResponseSolver({"test_solver", testSolve, {}});
  testing::SceneDir dir;
  meshes(dir);
  auto load = [&](const std::string& entry) {
    return scene::loadScene(dir.write("s.yaml", sceneYaml(entry)));
  };
  SECTION("an unknown method, both a response and a hull") {
    const auto r = load(
        "    hd: {body: barge, method: impulse_respons, hull: meshes/barge.stl}\n"
        "    he: {body: barge, method: impulse_response, hull: meshes/barge.stl, response: "
        "x.ysir}\n");
    const auto* d = find(r, "mechanics.hydrodynamics.hd.method");
    REQUIRE(d);
    CHECK_THAT(d->message + d->hint, Contains("did you mean 'impulse_response'?"));
    const auto* e = find(r, "mechanics.hydrodynamics.he");
    REQUIRE(e);
    CHECK(e->where.line == 17);
    CHECK_THAT(e->message, Contains("exactly one of 'response'"));
  }
  SECTION("a registered check's problem, with its numbers") {
    registerImpulseResponseSolver(
        {"checked", testSolve, [](const HydrodynamicsRequest&, const forces::AiryWaves& sea) {
           const double shortest = 2 * M_PI / sea.wavenumber(0);
           return std::vector<std::string>{
               "a free-surface panel of 12 m is longer than a tenth of the shortest wave (" +
               std::to_string(shortest) + " m)"};
         }});
    const auto r = load(
        "    hd: {body: barge, method: impulse_response, hull: meshes/barge.stl, solver: "
        "checked}\n");
    const auto* d = find(r, "mechanics.hydrodynamics.hd");
    REQUIRE(d);
    CHECK(d->where.line == 16);
    CHECK_THAT(d->message, Contains("shortest wave (99.9"));
  }
  SECTION("a damaged cache file: named, with what is wrong") {
    REQUIRE(load(kEntry).scene);  // (solved and cached)
    for (const auto& e : std::filesystem::directory_iterator(dir.path() / "cache"))
      std::ofstream(e.path(), std::ios::app) << "x";
    const auto r = load(kEntry);
    CHECK_FALSE(r.scene);
    CHECK_THAT(r.diagnostics.report(),
               Contains(".ysir: damaged (checksum mismatch)") && Contains("s.yaml:16"));
  }
  SECTION("an unknown solver, waves without excitation") {
    const auto r = load(
        "    hd: {body: barge, method: impulse_response, hull: meshes/barge.stl, solver: panel}\n"
        "    he: {body: barge, method: impulse_response, hull: meshes/barge.stl, solver: "
        "test_solver, cache: cache,\n"
        "         settings: {scale: 1}}\n");
    CHECK_THAT(find(r, "mechanics.hydrodynamics.hd.solver")->message,
               Contains("unknown solver") && Contains("test_solver"));
    CHECK_THAT(find(r, "mechanics.hydrodynamics.he")->message, Contains("no excitation"));
  }
}

// (before the next case, which replaces the registered rankine_td by its own)
TEST_CASE("a marched run longer than its free surface's growth allows is refused at the entry") {
  // (the box barge 6 x 4 m at 1 m draft on the free surface of the 2 rad/s RAO tests, whose short
  // waves grow at 0.0070 1/s: tests/forces/hydro/surface_growth_test.cpp) => until 1,000 s is
  // refused with the numbers; 200 s, or surface_damping 0.008 1/s, is taken
  testing::SceneDir dir;
  std::filesystem::create_directories(dir.path() / "meshes");
  forces::writeStl(forces::boxMesh(dynamics::Vector3(6, 4, 2), 6, 4, 2),
                   dir.file("meshes/box.stl"));
  auto yaml = [](const std::string& until, const std::string& more) {
    return "schema_version: 1\nintegrator: {method: rk4, dt: 0.05}\nuntil: " + until + R"(
mechanics:
  water: {density: 1025}
  bodies:
    box: {parent: world, joint: {type: free}, mass: 24600, inertia: [3.2e4, 8.0e4, 8.0e4]}
  hydrostatics:
    hull: {body: box, mesh: meshes/box.stl}
  hydrodynamics:
    hd: {body: box, method: rankine_td, hull: meshes/box.stl, dt: 0.05,
         settings: {truncation_radius: 42.54, first_spacing: 0.5, max_spacing: 1.5398, growth: 1.15,
                    longest_period: 3.14159)" +
           more + "}}\n";
  };
  const auto r = scene::loadScene(dir.write("long.yaml", yaml("1000", "")));
  INFO(r.diagnostics.report());
  const auto* d = find(r, "mechanics.hydrodynamics.hd");
  REQUIRE(d);
  CHECK(d->where.line == 11);
  CHECK(d->where.column == 29);
  CHECK_THAT(d->message,
             Contains("rankine_td: the free surface's short waves of the mesh grow at 0.00") &&
                 Contains("surface_damping to at least") && Contains("until = 1e+03 s"));
  for (const auto& [until, more] :
       {std::pair<std::string, std::string>{"200", ""}, {"1000", ", surface_damping: 0.008"}}) {
    const auto ok = scene::loadScene(dir.write("ok.yaml", yaml(until, more)));
    INFO(until << more << ": " << ok.diagnostics.report());
    CHECK(ok.scene);
  }
}

TEST_CASE("rankine_td is built by the method registered for it") {
  testing::SceneDir dir;
  meshes(dir);
  int built = 0;
  registerTimeDomainMethod(
      {"rankine_td",
       [&built](const std::string& name, const dynamics::Model& model, int body,
                const HydrodynamicsRequest& q, std::shared_ptr<const forces::AiryWaves> sea)
           -> std::unique_ptr<forces::ForceProvider> {
         ++built;
         CHECK(q.hull);
         CHECK(q.settings.at("panel_size") == 0.5);
         HydrodynamicsRequest r = q;
         r.settings["scale"] = 1;
         r.headings = {0.0};
         return std::make_unique<ImpulseResponseForce>(
             name, model, body, std::make_shared<const ImpulseResponse>(testSolve(r)), sea);
       },
       {},
       {},
       {},
       {}});
  const auto r = scene::loadScene(
      dir.write("s.yaml", sceneYaml("    hd: {body: barge, method: rankine_td, hull: "
                                    "meshes/barge.stl, settings: {panel_size: 0.5}}\n")));
  INFO(r.diagnostics.report());
  REQUIRE(r.scene);
  auto root = scene::assemble(*r.scene);
  CHECK(built >= 1);  // (the door's checks build the system too)
}

TEST_CASE("a hydrodynamics block in an included file sees the scene root's water and sea") {
  // (a crane-like file included by the root, its hydrodynamics by a registered method) => the
  // method's request and its door check get the root's depth and density, and its check the
  // root's sea (they used to get the default water: deep, and no sea)
  testing::SceneDir dir;
  meshes(dir);
  double depth = 0.0, density = 0.0;
  std::size_t components = 0;
  auto probe = [&](const HydrodynamicsRequest& q, const forces::AiryWaves& sea) {
    depth = q.water.depth;
    density = q.water.density;
    components = sea.size();
    return std::vector<std::string>{};
  };
  registerTimeDomainMethod(
      {"water_probe",
       [](const std::string& name, const dynamics::Model& model, int body,
          const HydrodynamicsRequest& q,
          std::shared_ptr<const forces::AiryWaves> sea) -> std::unique_ptr<forces::ForceProvider> {
         HydrodynamicsRequest r = q;
         r.settings["scale"] = 1;
         r.headings = {0.0};
         return std::make_unique<ImpulseResponseForce>(
             name, model, body, std::make_shared<const ImpulseResponse>(testSolve(r)), sea);
       },
       probe,
       {},
       {},
       {}});
  dir.write("barge.yaml", R"(schema_version: 1
mechanics:
  bodies:
    barge:
      parent: world
      joint: {type: free, q0: {xyz: [0, 0, 0.5]}}
      mass: 246000
      inertia: [1.64e6, 8.53e6, 9.51e6]
  hydrostatics:
    hull: {body: barge, mesh: meshes/barge.stl}
  hydrodynamics:
    hd: {body: barge, method: water_probe, hull: meshes/barge.stl}
)");
  const auto r = scene::loadScene(dir.write("s.yaml", R"(schema_version: 1
integrator: {method: rk4, dt: 0.02}
components:
  crane: {include: barge.yaml}
mechanics:
  water:
    density: 1020
    depth: 20
    waves: [{height: 1, period: 8}, {height: 0.5, period: 6}]
)"));
  INFO(r.diagnostics.report());
  REQUIRE(r.scene);
  CHECK(depth == 20.0);
  CHECK(density == 1020.0);
  CHECK(components == 2);
}

TEST_CASE("a sea component above the response's resolved frequency is refused at the entry") {
  // (a response whose excitation window's cutoff is 0.6 rad/s) => the sea's 8 s wave (0.785
  // rad/s) lies above what it resolves: refused at the entry's method, naming the component;
  // a 12 s wave (0.524 rad/s) is taken
  testing::SceneDir dir;
  meshes(dir);
  HydrodynamicsRequest q;
  q.settings["scale"] = 1;
  q.headings = {0.0};
  ImpulseResponse ir = testSolve(q);
  ir.key = "given";
  ir.excitationWindow = 0.6;
  writeImpulseResponse(ir, dir.path() / "barge.ysir");
  const std::string entry =
      "    hd: {body: barge, method: impulse_response, response: barge.ysir}\n";
  const auto r = scene::loadScene(dir.write("s.yaml", sceneYaml(entry)));
  const auto* d = find(r, "mechanics.hydrodynamics.hd");
  REQUIRE(d);
  CHECK(d->where.line == 16);
  CHECK(d->where.column == 31);
  CHECK_THAT(d->message,
             Contains("1 of the sea's 1 wave components lie above the impulse response's "
                      "resolved frequency 0.6 rad/s") &&
                 Contains("component 1 at 0.785 rad/s (period 8 s, height 1 m)") &&
                 Contains("a longer tp"));
  std::string calm = sceneYaml(entry);
  calm.replace(calm.find("period: 8"), 9, "period: 12");
  const auto ok = scene::loadScene(dir.write("ok.yaml", calm));
  INFO(ok.diagnostics.report());
  CHECK(ok.scene);
}
