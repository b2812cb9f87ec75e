// Regression test of examples/megablock_floating_crane/rankine_td.yaml and rankine_td_sea.yaml
// (the same solver in scene.yaml's sea on a free surface that resolves it: its text against
// scene.yaml's, and the door takes it). rankine_td.yaml: the mega-block operation
// in calm water with the floating crane's radiation by the time-domain Rankine solver marched
// with the run (the full 450 s run takes more than a minute of CPU: README.md, "The Rankine
// solver marched with the run"). The file is scene.yaml but for its header, its name, `sea` and
// the crane's `hydrodynamics` parameter; the first 40 s of both in calm water (the block hanging,
// then hoisted from 5 s) give the same statics, nearly the same added mass from the same panels,
// and the same rope tensions to a small fraction of their static levels.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "devs/simulator.hpp"
#include "dynamics/model.hpp"
#include "models/multibody/multibody_model.hpp"
#include "scene/assembler.hpp"
#include "scene/scene_loader.hpp"
#include "support/channel_reader.hpp"
#include "support/test_paths.hpp"

using namespace yardsim;

namespace {
constexpr double kTol = 0.002;  // of a rope's static tension: 5e-4 measured (README.md)
const std::string kDir = std::string(YARDSIM_SOURCE_DIR) + "/examples/megablock_floating_crane/";

// (scene file) => its lines after the header comment, without the `name:` line and without the
// floating crane's `hydrodynamics:` parameter (the lines indented below it)
std::vector<std::string> body(const std::string& file) {
  std::ifstream in(file);
  REQUIRE(in);
  std::vector<std::string> out;
  std::string line;
  bool header = true, skipping = false;
  while (std::getline(in, line)) {
    if (header && line.rfind("#", 0) == 0) continue;
    header = false;
    if (line.rfind("name: ", 0) == 0) continue;
    if (line.rfind("  sea:", 0) == 0) {  // (the sea parameter, to the next unindented key)
      skipping = true;
      continue;
    }
    if (line ==
        "      hydrodynamics:          # the time-domain Rankine solver marched with the run "
        "(header)") {
      skipping = true;
      continue;
    }
    if (skipping && line.rfind("    ", 0) == 0) continue;
    skipping = false;
    out.push_back(line);
  }
  return out;
}

// (variant file) => its body() is scene.yaml's, line for line
void checkSameBody(const std::string& file) {
  const auto variant = body(kDir + file), scene = body(kDir + "scene.yaml");
  REQUIRE(scene.size() > 150);
  REQUIRE(variant.size() == scene.size());
  for (std::size_t k = 0; k < scene.size(); ++k) {
    INFO(file << ": line " << k << " after the header");
    CHECK(variant[k] == scene[k]);
  }
}

// One run of a scene in calm water to 40 s: the rope tensions at rest (4 s) and every 0.5 s, the
// barge's added mass and the energy balance's drift
struct Run {
  std::map<std::string, double> still;
  std::map<std::string, std::vector<double>> history;
  dynamics::Matrix6 addedMass;
  double drift = 0.0, hung = 0.0;
};

Run run(const std::string& file) {
  scene::ParamOverrides o;
  scene::ParamOverride& calm = o["sea"];
  calm.value = YAML::Load("[]");
  calm.where.file = "megablock_rankine_td_test.cpp";
  calm.keyPath = "params.sea";
  auto loaded = scene::loadScene(kDir + file, o);
  INFO(loaded.diagnostics.report());
  REQUIRE(loaded.scene);
  auto root = scene::assemble(*loaded.scene);
  devs::Simulator sim(*root);
  const auto& mb = static_cast<const models::MultibodyModel&>(*root->findComponent("mechanics"));
  const testing::ChannelReader read(mb);
  const dynamics::Model& m = mb.mechanics();
  Run r;
  r.addedMass = m.addedMass[static_cast<std::size_t>(m.bodyIndex("FC.barge"))];
  for (const char* b : {"block", "loader_clamp", "loader_beam", "FC.hook"})
    r.hung += m.inertias[m.bodyIndex(b)].mass;
  sim.runUntil(4.0);
  for (const auto& [name, c] : read.byName)
    if (name.size() > 8 && name.substr(name.size() - 8) == ".tension") r.still[name] = c.read();
  const double balance0 = read("mechanics.energy_balance");
  for (double t = 4.5; t <= 40.0 + 1e-9; t += 0.5) {
    sim.runUntil(t);
    r.drift = std::max(r.drift, std::abs(read("mechanics.energy_balance") - balance0));
    for (const auto& [name, s] : r.still) r.history[name].push_back(read(name));
  }
  return r;
}
}  // namespace

TEST_CASE(
    "megablock rankine_td: the variant is the main scene but for the sea and the crane's "
    "hydrodynamics") {
  checkSameBody("rankine_td.yaml");
}

TEST_CASE(
    "megablock rankine_td_sea: the variant is the main scene, sea included, but for the crane's "
    "hydrodynamics") {
  checkSameBody("rankine_td_sea.yaml");
  // (the sea parameter itself, which body() leaves out) => the same lines in both files
  const auto seaLines = [](const std::string& file) {
    std::ifstream in(file);
    std::vector<std::string> out;
    std::string line;
    bool inSea = false;
    while (std::getline(in, line)) {
      if (line.rfind("  sea:", 0) == 0)
        inSea = true;
      else if (inSea && line.rfind("    ", 0) != 0)
        inSea = false;
      if (inSea) out.push_back(line);
    }
    return out;
  };
  const auto sea = seaLines(kDir + "scene.yaml");
  REQUIRE(sea.size() >= 3);
  CHECK(seaLines(kDir + "rankine_td_sea.yaml") == sea);
}

TEST_CASE("megablock rankine_td_sea: the door takes its free surface in the scene's sea",
          "[long]") {
  // (the file as it is: scene.yaml's sea) => valid: every free-surface panel inside the damping
  // zone at most a tenth of the shortest wave, 0.2 s within the emp limit, the sea within the
  // resolved band, and the free surface's growth bounded over the scene's 450 s (the loader's
  // run-length check: an eigenvalue problem of order 5,884, most of this test's two minutes of CPU)
  const auto loaded = scene::loadScene(kDir + "rankine_td_sea.yaml", {});
  INFO(loaded.diagnostics.report());
  CHECK(loaded.scene);
  CHECK_FALSE(loaded.diagnostics.hasErrors());
}

TEST_CASE(
    "megablock rankine_td: statics and added mass and tensions agree with the impulse response",
    "[long]") {
  const Run ir = run("scene.yaml"), td = run("rankine_td.yaml");
  // (hanging still: no memory force) => the same equilibrium on both paths
  REQUIRE(ir.still.size() == 13);
  for (const auto& [name, s] : ir.still) {
    INFO(name);
    CHECK(td.still.at(name) == Approx(s).epsilon(1e-6));
  }
  // (the same panels, the response at a 3.0 m draft, the marched model at the crane's start
  // pose, 3.16 m) => A-infinity in heave, roll and pitch within 2 % ([angular; linear])
  for (const int k : {0, 1, 5}) {
    INFO("diagonal element " << k << ": response " << ir.addedMass(k, k) << ", marched "
                             << td.addedMass(k, k));
    CHECK(td.addedMass(k, k) == Approx(ir.addedMass(k, k)).epsilon(0.02));  // 0.6-0.9 %
  }
  // (the hoist from 5 s) => every rope's tension on the two paths within kTol of its static level
  // at every 0.5 s, while the hoist's start moves it by more than that
  for (const auto& [name, s] : ir.still) {
    const auto &a = ir.history.at(name), &b = td.history.at(name);
    REQUIRE(a.size() == b.size());
    double apart = 0.0, moved = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k) {
      apart = std::max(apart, std::abs(a[k] - b[k]) / s);
      moved = std::max(moved, std::abs(a[k] - s) / s);
    }
    INFO(name << ": the paths " << apart << " of static apart, the tension moves " << moved);
    CHECK(apart < kTol);
    CHECK(moved > 2 * apart);
  }
  // energy: closed on the marched path as on the other, to 1e-3 of lifting the hung mass 1 m
  INFO("energy balance drift: impulse response " << ir.drift << " J, marched " << td.drift << " J");
  CHECK(td.drift < 1e-3 * td.hung * 9.81);
  CHECK(ir.drift < 1e-3 * ir.hung * 9.81);
}
