// The `mooring:` key of scene/providers/: catenary lines read from YAML, their channels against
// an independent solve of the same catenary (forces/lines/catenary.hpp), a moored body's static
// offset under a steady force against the balance of the two lines' horizontal tensions and
// against F / K with K the lines' analytic horizontal stiffness, the energy balance of a free
// surge oscillation, and problems reported at their YAML nodes; lumped lines in the scene's current
// and waves against Morison's drag and inertia per node.
#include <catch2/catch.hpp>
#include <cmath>

#include "forces/airy_waves.hpp"
#include "forces/lines/catenary.hpp"
#include "mechanics/build.hpp"
#include "mechanics/data.hpp"
#include "mechanics/set_points.hpp"
#include "mechanics/stage.hpp"
#include "mechanics/system.hpp"
#include "run/runner.hpp"
#include "scene/assembler.hpp"
#include "scene/mechanical_systems.hpp"
#include "scene/scene_loader.hpp"
#include "support/csv_file.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;
using Catch::Matchers::Contains;

namespace {

// (the chain: 450 m, EA 1e9 N, 1000 N/m in water; anchors 400 m either side, 100 m down)
const forces::CatenaryParameters kChain{450.0, 1.0e9, 1000.0, true, 0.0};

// a 1e5 kg body on a surge slider between two lines, pushed by a steady force F
std::string moored(double force, double q0, bool equilibrium, const std::string& extra = "") {
  const std::string f = std::to_string(force);
  return R"(schema_version: 1
integrator: {method: rk4, dt: 0.01}
mechanics:
  gravity: [0, 0, 0]
  equilibrium: )" +
         std::string(equilibrium ? "true" : "false") + R"(
  bodies:
    buoy:
      parent: world
      joint: {name: surge, type: prismatic, axis: [1, 0, 0], q0: )" +
         std::to_string(q0) + R"(}
      mass: 1.0e5
      inertia: [1, 1, 1]
  loads:
    push: {body: buoy, series: [[0, )" +
         f + ", 0, 0, 0, 0, 0], [1000, " + f + R"(, 0, 0, 0, 0, 0]]}
  mooring:
    west: {anchor: [-400, 0, -100], fairlead: {body: buoy, point: [0, 0, 0]}, length: 450, EA: 1.0e9, weight: 1000}
    east: {anchor: [400, 0, -100], fairlead: {body: buoy}, length: 450, EA: 1.0e9, weight: 1000}
)" + extra +
         R"(record: {interval: 0.5, channels: ["surge.q", "west.*", "east.*", "mechanics.energy_balance", "mechanics.work"]}
)";
}

// (scene text, until) => its timeseries.csv after a run
testing::CsvFile simulate(const testing::SceneDir& dir, const std::string& text, double until) {
  auto scene = scene::loadSceneOrThrow(dir.write("s.yaml", text));
  auto root = scene::assemble(*scene);
  run::runScene(*scene, *root, {dir.path() / "out", until, {}, {}, 0.1});
  return testing::CsvFile((dir.path() / "out" / "timeseries.csv").string());
}

}  // namespace

TEST_CASE("mooring: channels equal an independent catenary solve at the fairlead") {
  testing::SceneDir dir;
  const auto csv = simulate(dir, moored(0.0, 3.0, false), 0.5);
  REQUIRE(!csv.rows.empty());
  const auto c = forces::solveCatenary(kChain, 403.0, 100.0);  // west: the span grew by 3 m
  REQUIRE(c.status == forces::CatenaryStatus::Converged);
  REQUIRE(c.profile == forces::CatenaryProfile::TouchingDown);
  const auto& r = csv.rows[0];
  auto at = [&](const char* name) {
    const int k = csv.column(name);
    REQUIRE(k > 0);
    return r[k];
  };
  CHECK(at("west.fairlead_tension[N]") == Approx(std::hypot(c.hf, c.vf)).epsilon(1e-9));
  CHECK(at("west.horizontal_tension[N]") == Approx(c.hf).epsilon(1e-9));
  CHECK(at("west.anchor_tension[N]") == Approx(std::hypot(c.ha, c.va)).epsilon(1e-9));
  CHECK(at("west.fairlead_angle[rad]") == Approx(std::atan2(c.vf, c.hf)).epsilon(1e-9));
  CHECK(at("west.anchor_angle[rad]") == Approx(std::atan2(c.va, c.ha)).margin(1e-12));
  CHECK(at("west.laid_length[m]") == Approx(c.laidLength).epsilon(1e-9));
  CHECK(at("west.touchdown_distance[m]") == Approx(c.touchdownX).epsilon(1e-9));
  CHECK(at("west.touchdown_x[m]") == Approx(-400.0 + c.touchdownX).epsilon(1e-9));
  CHECK(at("west.touchdown_y[m]") == Approx(0.0).margin(1e-9));
  // (a sinking line on a bed without friction) => the anchor feels the touchdown tension HF
  CHECK(c.laidLength > 0);
  CHECK(at("west.anchor_tension[N]") == Approx(c.hf).epsilon(1e-9));
}

TEST_CASE("mooring: a moored body's static offset under a steady force balances the lines") {
  testing::SceneDir dir;
  const double F = 2.0e4;  // N
  const auto csv = simulate(dir, moored(F, 0.0, true), 0.5);
  const int q = csv.column("surge.q[m]"), hw = csv.column("west.horizontal_tension[N]"),
            he = csv.column("east.horizontal_tension[N]");
  REQUIRE(std::min({q, hw, he}) > 0);
  const double x = csv.rows[0][q];
  // (exact) => HF_west(400 + x) - HF_east(400 - x) = F, solved independently
  const auto west = forces::solveCatenary(kChain, 400.0 + x, 100.0);
  const auto east = forces::solveCatenary(kChain, 400.0 - x, 100.0);
  CHECK(west.hf - east.hf == Approx(F).epsilon(1e-6));
  CHECK(csv.rows[0][hw] - csv.rows[0][he] == Approx(F).epsilon(1e-6));
  // (linear) => x = F / K, K = dHF/dXF of both lines at the centre (the catenary stiffness)
  const auto centre = forces::solveCatenary(kChain, 400.0, 100.0);
  const double K = 2.0 * centre.k11;
  INFO("K = " << K << " N/m, x = " << x << " m, F/K = " << F / K << " m");
  CHECK(x == Approx(F / K).epsilon(0.02));
}

TEST_CASE("mooring: a released moored body oscillates with its energy balance closed") {
  testing::SceneDir dir;
  const auto csv = simulate(dir, moored(0.0, 2.0, false), 60.0);
  const int q = csv.column("surge.q[m]"), balance = csv.column("mechanics.energy_balance[J]"),
            energy = csv.column("west.energy[J]");
  REQUIRE(std::min({q, balance, energy}) > 0);
  // (small surge) => period 2 pi sqrt(m / K) within the nonlinearity of a 2 m amplitude
  const auto centre = forces::solveCatenary(kChain, 400.0, 100.0);
  const double period = 2 * M_PI * std::sqrt(1.0e5 / (2.0 * centre.k11));
  std::vector<double> up;
  for (std::size_t k = 1; k < csv.rows.size(); ++k) {
    const double a = csv.rows[k - 1][q], b = csv.rows[k][q];
    if (a < 0 && b >= 0) up.push_back(csv.rows[k - 1][0] + 0.5 * -a / (b - a));
    CHECK(std::abs(csv.rows[k][balance] - csv.rows[0][balance]) < 1e-6 * 1e5);
  }
  REQUIRE(up.size() >= 2);
  CHECK((up.back() - up.front()) / static_cast<double>(up.size() - 1) ==
        Approx(period).epsilon(0.03));
}

TEST_CASE("mooring: sea-bed friction lowers the anchor tension and the energy balance closes") {
  testing::SceneDir dir;
  // (CB = 1 on both lines, fully mobilised toward the fairlead: the FAST assumption) => the
  // anchor feels max(0, HF - CB w LB); the line force stays a function of the fairlead position,
  // so in surge alone it does not damp, and the line's power F . v + dV/dt keeps the balance
  std::string text = moored(0.0, 2.0, false);
  const std::string from = "weight: 1000}", to = "weight: 1000, friction: 1.0}";
  for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  REQUIRE(text.find("friction") != std::string::npos);
  const auto csv = simulate(dir, text, 60.0);
  const int q = csv.column("surge.q[m]"), balance = csv.column("mechanics.energy_balance[J]"),
            anchor = csv.column("west.anchor_tension[N]"),
            hf = csv.column("west.horizontal_tension[N]"), laid = csv.column("west.laid_length[m]");
  REQUIRE(std::min({q, balance, anchor, hf, laid}) > 0);
  forces::CatenaryParameters rough = kChain;
  rough.friction = 1.0;
  const auto c = forces::solveCatenary(rough, 402.0, 100.0);
  const auto& r0 = csv.rows[0];
  CHECK(r0[hf] == Approx(c.hf).epsilon(1e-9));
  CHECK(r0[laid] == Approx(c.laidLength).epsilon(1e-9));
  CHECK(r0[anchor] == Approx(std::max(0.0, c.hf - 1.0 * 1000.0 * c.laidLength)).margin(1e-6));
  CHECK(r0[anchor] < r0[hf]);
  double worst = 0, energy = 0;
  const int e = csv.column("west.energy[J]");
  REQUIRE(e > 0);
  for (const auto& r : csv.rows) {
    worst = std::max(worst, std::abs(r[balance] - r0[balance]));
    energy = std::max(energy, std::abs(r[e] - r0[e]));
  }
  INFO("worst balance " << worst << " J, line energy swing " << energy << " J");
  CHECK(worst < 1e-6 * energy);
}

TEST_CASE("mooring: problems at their nodes, with did you mean") {
  testing::SceneDir dir;
  const auto typo = scene::loadScene(dir.write(
      "a.yaml", moored(0.0, 0.0, false,
                       "    north: {anchor: [0, 400, -100], fairled: {body: buoy}, length: 450, "
                       "weight: 1000}\n")));
  CHECK_FALSE(typo.scene);
  CHECK_THAT(typo.diagnostics.report(), Contains("a.yaml:") && Contains("fairled") &&
                                            Contains("fairlead") &&
                                            Contains("missing required key 'fairlead'"));
  const auto bad = scene::loadScene(dir.write(
      "b.yaml", moored(0.0, 0.0, false,
                       "    north: {anchor: {body: buoy}, fairlead: {body: buoy}, length: -1, "
                       "seabed: true}\n    south: {anchor: [0, -400, -100], fairlead: {body: "
                       "buoy}, length: 450, mass: 100, diameter: 0.2, friction: 0.5, seabed: "
                       "false}\n")));
  CHECK_FALSE(bad.scene);
  CHECK_THAT(bad.diagnostics.report(), Contains("missing 'weight'") &&
                                           Contains("needs its anchor in the world") &&
                                           Contains("set seabed: true") && Contains("b.yaml:"));
}

TEST_CASE("mooring: lumped lines' problems at their nodes") {
  testing::SceneDir dir;
  const auto bad = scene::loadScene(dir.write(
      "c.yaml",
      moored(0.0, 0.0, false,
             "    north: {model: lumped, anchor: [0, 400, -100], fairlead: {body: buoy}, "
             "length: 450, weight: 1000, EA: 1e9}\n"
             "    south: {model: lumped, anchor: [0, -400, -100], fairlead: {body: buoy}, "
             "length: 450, EA: 1e9, mass: 100, diameter: 0.2, segments: 2.5, damping: 1, "
             "damping_ratio: 0.5}\n"
             "    up: {model: lumpy, anchor: [0, 0, -100], fairlead: {body: buoy}, length: 450, "
             "weight: 1000}\n"
             "    down: {anchor: [0, 0, -100], fairlead: {body: buoy}, length: 450, "
             "weight: 1000, segments: 20}\n")));
  CHECK_FALSE(bad.scene);
  const std::string report = bad.diagnostics.report();
  INFO(report);
  CHECK_THAT(report, Contains("c.yaml:") && Contains("needs 'mass' (kg/m in air) and 'diameter'") &&
                         Contains("whole number of segments") &&
                         Contains("either damping (N s) or damping_ratio") &&
                         Contains("expected catenary or lumped, got 'lumpy'") &&
                         Contains("'segments' is a key of model: lumped"));
}

TEST_CASE("mooring: a lumped line's nodes are bodies of the system with their channels") {
  testing::SceneDir dir;
  std::string text =
      moored(0.0, 0.0, false,
             "    north: {model: lumped, anchor: [0, 400, -100], fairlead: {body: buoy}, "
             "length: 450, EA: 1e9, mass: 130, diameter: 0.12, segments: 8}\n");
  text.replace(text.find("\"east.*\""), 8, "\"east.*\", \"north.*\"");
  const auto csv = simulate(dir, text, 0.2);
  REQUIRE(!csv.rows.empty());
  // (the nodes 1 .. 7) => positions as body channels, on the anchor-fairlead plane x = 0
  for (int i = 1; i < 8; ++i) {
    const int x = csv.column("north.node" + std::to_string(i) + ".x[m]");
    const int y = csv.column("north.node" + std::to_string(i) + ".y[m]");
    REQUIRE(x > 0);
    CHECK(std::abs(csv.rows[0][x]) < 1e-9);
    CHECK(csv.rows[0][y] > 0.0);
  }
  CHECK(csv.column("north.node8.x[m]") < 0);  // the fairlead end is the buoy's point
  CHECK(csv.column("north.fairlead_tension[N]") > 0);
  CHECK(csv.column("north.anchor_tension[N]") > 0);
}

namespace {

// (line along `axis` (x or y) from [0, 0, -20] to a fixed post 100 m away, water keys) => the
// system built from the scene, and each inner node's acceleration at q0 (at rest) and time t
struct LumpedInSea {
  std::unique_ptr<mechanics::BuiltMechanics> mech;
  Eigen::VectorXd a;
  int nodeV(const std::string& node) const {
    const int b = mech->model.bodyIndex(node);
    REQUIRE(b > 0);
    return mech->model.idxV[b];
  }
};
LumpedInSea lumpedInSea(const testing::SceneDir& dir, char axis, const std::string& water,
                        const std::string& keys, double t, double density = 1025.0) {
  const std::string post = axis == 'x' ? "[100, 0, -20]" : "[0, 100, -20]";
  const std::string text = R"(schema_version: 1
integrator: {method: hht, dt: 0.05}
mechanics:
  gravity: [0, 0, 0]
  water: {density: )" + std::to_string(density) +
                           R"(, level: 0.0, depth: 40.0)" + water + R"(}
  bodies:
    post: {parent: world, joint: {type: fixed}, placement: {xyz: )" +
                           post + R"(}, mass: 1.0e3, inertia: [1, 1, 1]}
  mooring:
    line: {model: lumped, anchor: [0, 0, -20], fairlead: {body: post}, length: 99.9, EA: 1.0e8,
           mass: 80, diameter: 0.1, segments: 4, seabed: false)" +
                           keys + R"(}
until: 1
)";
  auto scene = scene::loadSceneOrThrow(dir.write("s.yaml", text));
  REQUIRE(scene->systems.size() == 1);
  LumpedInSea out;
  out.mech = std::make_unique<mechanics::BuiltMechanics>(
      mechanics::buildMechanics(scene->systems[0]->spec));
  const mechanics::System system(*out.mech, {}, "sea");
  mechanics::Data data(system);
  const auto& model = out.mech->model;
  mechanics::SetPoints held{
      std::vector<mechanics::JointDrive>(static_cast<std::size_t>(model.nbodies)),
      std::vector<mechanics::ActorLoad>(static_cast<std::size_t>(model.nbodies)),
      std::vector<mechanics::WinchJob>(system.ropes().size())};
  data.setPoints = &held;
  mechanics::connectStage(system, data);
  out.a.setZero(model.nv);
  data.kernel.acceleration(t, out.mech->q0, out.mech->v0, out.a);
  return out;
}

constexpr double kRhoW = 1025.0, kD = 0.1, kMu = 80.0, kL = 99.9 / 4;

}  // namespace

TEST_CASE("mooring: a lumped line in the scene's current feels Morison drag per node") {
  // (line along x, uniform current towards +y across it) => per inner node 1/2 rho Cdn d l_s U^2
  // across, l_s its stretched length, over its mass mu l + rho V Can; none in still water
  testing::SceneDir dir;
  const double U = 1.5, cdn = 1.1;
  const auto sea = lumpedInSea(dir, 'x', ", current: {speed: 1.5, direction_deg: 90}",
                               ", cdn: 1.1, can: 0.8", 0.0);
  const auto calm = lumpedInSea(dir, 'x', "", ", cdn: 1.1, can: 0.8", 0.0);
  const Eigen::VectorXd& q = sea.mech->q0;
  auto at = [&](int i) -> Eigen::Vector3d {
    if (i == 0) return {0, 0, -20};
    if (i == 4) return {100, 0, -20};
    return q.segment<3>(
        sea.mech->model.idxQ[sea.mech->model.bodyIndex("line.node" + std::to_string(i))]);
  };
  const double m = (kMu + kRhoW * 0.25 * M_PI * kD * kD * 0.8) * kL;
  for (int i = 1; i < 4; ++i) {
    const double ls = 0.5 * ((at(i) - at(i - 1)).norm() + (at(i + 1) - at(i)).norm());
    const int k = sea.nodeV("line.node" + std::to_string(i));
    INFO("node " << i);
    CHECK(sea.a[k + 1] == Approx(0.5 * kRhoW * cdn * kD * ls * U * U / m).epsilon(1e-9));
    CHECK(std::abs(calm.a[k + 1]) < 1e-12);
  }
}

TEST_CASE("mooring: a lumped line in the scene's waves feels the Morison inertia per node") {
  // (line along y, waves towards +x, no drag) => per inner node rho V (1 + Can) a_w across it, a_w
  // the water's acceleration there (forces::AiryWaves, checked against Airy's closed form in
  // tests/forces/airy_waves_test.cpp), over its mass mu l + rho V Can
  testing::SceneDir dir;
  const double t = 1.3, can = 0.8;
  const auto sea = lumpedInSea(dir, 'y', ", waves: [{height: 2.0, period: 8.0, direction_deg: 0}]",
                               ", cdn: 0, cdt: 0, can: 0.8", t);
  forces::WaterProperties water;
  water.depth = 40.0;
  const forces::AiryWaves waves(water, {forces::WaveComponent{2.0, 8.0, 0.0, 0.0}});
  const double V = 0.25 * M_PI * kD * kD * kL, m = kMu * kL + kRhoW * V * can;
  int checked = 0;
  for (int i = 1; i < 4; ++i) {
    const std::string node = "line.node" + std::to_string(i);
    const Eigen::Vector3d p =
        sea.mech->q0.segment<3>(sea.mech->model.idxQ[sea.mech->model.bodyIndex(node)]);
    const double aw = waves.acceleration(p, t).x();
    INFO(node << ": water acceleration " << aw << " m/s^2");
    CHECK(std::abs(aw) > 0.05);
    CHECK(sea.a[sea.nodeV(node)] == Approx(kRhoW * V * (1.0 + can) * aw / m).epsilon(1e-9));
    ++checked;
  }
  CHECK(checked == 3);
}

TEST_CASE("mooring: a lumped line takes the scene's water density unless it gives its own") {
  // (scene water 1000 kg/m^3, a current across the line) => per inner node the drag
  // 1/2 rho Cdn d l_s U^2 over the mass (mu + rho A Can) l with rho = 1000; with the line's own
  // water_density: 1025 the same with 1025; the node bodies' masses alike
  testing::SceneDir dir;
  const double U = 1.5, cdn = 1.1, can = 0.8, A = 0.25 * M_PI * kD * kD;
  const std::string current = ", current: {speed: 1.5, direction_deg: 90}";
  const auto scene = lumpedInSea(dir, 'x', current, ", cdn: 1.1, can: 0.8", 0.0, 1000.0);
  const auto own =
      lumpedInSea(dir, 'x', current, ", cdn: 1.1, can: 0.8, water_density: 1025", 0.0, 1000.0);
  for (const auto* c : {&scene, &own}) {
    const double rho = c == &scene ? 1000.0 : 1025.0;
    const auto& model = c->mech->model;
    auto at = [&](int i) -> Eigen::Vector3d {
      if (i == 0) return {0, 0, -20};
      if (i == 4) return {100, 0, -20};
      return c->mech->q0.segment<3>(model.idxQ[model.bodyIndex("line.node" + std::to_string(i))]);
    };
    const double m = (kMu + rho * A * can) * kL;
    for (int i = 1; i < 4; ++i) {
      const std::string node = "line.node" + std::to_string(i);
      const double ls = 0.5 * ((at(i) - at(i - 1)).norm() + (at(i + 1) - at(i)).norm());
      INFO(node << " at rho " << rho);
      CHECK(model.inertias[model.bodyIndex(node)].mass == Approx(m).epsilon(1e-12));
      CHECK(c->a[c->nodeV(node) + 1] ==
            Approx(0.5 * rho * cdn * kD * ls * U * U / m).epsilon(1e-9));
    }
  }
}
