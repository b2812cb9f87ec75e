// Regression test of examples/megablock_floating_crane (Ha et al. 2015, §4.3), shortened with
// the scene's parameters (2 m hoist, 10 m transport, 2 m hoist down; the full run is in
// .ci/run): the statics while the block hangs still (the parts' tensions carry the weights),
// the action list in order, the block carried and lowered by what the actors asked, every
// rope's peak over static in a stated band, the floating crane's heel and trim small, and the
// energy balance closed.
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <string>
#include <utility>

#include "devs/simulator.hpp"
#include "dynamics/model.hpp"
#include "models/multibody/multibody_model.hpp"
#include "scene/assembler.hpp"
#include "scene/scene_loader.hpp"
#include "support/channel_reader.hpp"
#include "support/record_collector.hpp"
#include "support/test_paths.hpp"

using namespace yardsim;

namespace {
constexpr double kG = 9.81;

using Reader = testing::ChannelReader;

const char* kGoliath[] = {"GOC201.upper_fore", "GOC201.upper_aft",  "GOC201.lower_fore",
                          "GOC201.lower_aft",  "GOC202.upper_fore", "GOC202.upper_aft",
                          "GOC202.lower_fore", "GOC202.lower_aft"};
const char* kSlings[] = {"sling1", "sling2", "sling3", "sling4"};

// (name, value) => a parameter override as a sweep gives it
void give(scene::ParamOverrides& o, const std::string& name, const std::string& value) {
  scene::ParamOverride& v = o[name];
  v.value = YAML::Load(value);
  v.where.file = "megablock_floating_crane_test.cpp";
  v.keyPath = "params." + name;
}
}  // namespace

// At rest in calm water (the scene starts in static equilibrium; its sea is taken away, and at
// 4 s it would not have begun anyway): every rope pulls along the straight line between its two
// ends with its parts times its tension, so the vertical components can be summed per body
// group from the tensions and the ends' positions (the bodies' pose channels) alone, and each
// group's balance is a closed form. The block with its loader (clamp and beam) hangs on the eight
// goliath ropes and the four slings, clear of the water: their vertical pulls sum to its weight.
// The hook hangs on the 16 hoist parts and carries the slings: the hoist's vertical pull is its
// weight plus the slings' downward pull. The floating crane with its hook (no other vertical
// force on them: the carriage's bushing and the wind are horizontal) displaces its mass plus the
// slings' downward pull over g. (The ends' distance is checked against each rope's length
// channel: the geometry is the rope's own.)
TEST_CASE(
    "megablock with a floating crane: at rest the ropes' vertical pulls carry the block and the "
    "crane displaces its mass plus the slings' pull",
    "[long]") {
  scene::ParamOverrides o;
  give(o, "sea", "[]");
  auto loaded = scene::loadScene(
      std::string(YARDSIM_SOURCE_DIR) + "/examples/megablock_floating_crane/scene.yaml", o);
  INFO(loaded.diagnostics.report());
  REQUIRE(loaded.scene);
  auto root = scene::assemble(*loaded.scene);
  devs::Simulator sim(*root);
  const auto& mb = static_cast<const models::MultibodyModel&>(*root->findComponent("mechanics"));
  const Reader read(mb);
  const dynamics::Model& m = mb.mechanics();
  auto mass = [&](const std::string& b) { return m.inertias[m.bodyIndex(b)].mass; };
  sim.runUntil(4.0);
  REQUIRE(mb.state().x.v.cwiseAbs().maxCoeff() < 1e-6);
  REQUIRE(read("collision.points") == 0.0);

  // (rope, parts, body and point of the end pulled, body and point of the other end) => the
  // vertical force of the rope on the first body, N
  auto pullZ = [&](const std::string& rope, int parts, const std::string& body,
                   const Eigen::Vector3d& p, const std::string& other, const Eigen::Vector3d& q) {
    const Eigen::Vector3d d = read.world(other, q) - read.world(body, p);
    INFO(rope);
    CHECK(d.norm() == Approx(read(rope + ".length")).epsilon(1e-9));
    return parts * read(rope + ".tension") * d.z() / d.norm();
  };
  // the goliath ropes: the trolleys' points [-1 | 1, 0, 0] to the lugs the scene passes in
  struct Lug {
    const char* rope;
    const char* trolley;
    double x;
    const char* body;
    Eigen::Vector3d lug;
  };
  const Lug lugs[] = {
      {"GOC201.upper_fore", "GOC201.upper_trolley", -1, "loader_beam", {-7, 0, 1.5}},
      {"GOC201.upper_aft", "GOC201.upper_trolley", 1, "loader_beam", {-5, 0, 1.5}},
      {"GOC201.lower_fore", "GOC201.lower_trolley", -1, "block", {-21, -16, 0}},
      {"GOC201.lower_aft", "GOC201.lower_trolley", 1, "block", {-19, -16, 0}},
      {"GOC202.upper_fore", "GOC202.upper_trolley", -1, "loader_beam", {5, 0, 1.5}},
      {"GOC202.upper_aft", "GOC202.upper_trolley", 1, "loader_beam", {7, 0, 1.5}},
      {"GOC202.lower_fore", "GOC202.lower_trolley", -1, "block", {-9, -16, 0}},
      {"GOC202.lower_aft", "GOC202.lower_trolley", 1, "block", {-7, -16, 0}}};
  // the slings: the hook's points to the block's +x end
  const std::pair<Eigen::Vector3d, Eigen::Vector3d> slings[] = {
      {{-1, 1, -3}, {24, -10, 6}}, {{1, 1, -3}, {14, -10, 6}},
      {{1, -1, -3}, {14, 10, 6}},  {{-1, -1, -3}, {24, 10, 6}}};

  // 1. the block and its loader: sum of the vertical pulls = their weight (no buoyancy: the
  // block's bottom is 4 m above the water; the wind on it is horizontal)
  REQUIRE(read("block.z") - 6.0 > 0.0);
  double onBlock = 0.0, onHook = 0.0;
  for (const Lug& l : lugs)
    onBlock += pullZ(l.rope, 4, l.body, l.lug, l.trolley, Eigen::Vector3d(l.x, 0, 0));
  for (int k = 0; k < 4; ++k) {
    const std::string s = "sling" + std::to_string(k + 1);
    onBlock += pullZ(s, 1, "block", slings[k].second, "FC.hook", slings[k].first);
    onHook += pullZ(s, 1, "FC.hook", slings[k].first, "block", slings[k].second);
  }
  const double block = mass("block") + mass("loader_clamp") + mass("loader_beam");
  REQUIRE(block == Approx(3.55e6));
  INFO("vertical pull on the block " << onBlock << " N, its weight " << block * kG << " N");
  CHECK(onBlock == Approx(block * kG).epsilon(1e-6));
  CHECK(onHook < 0.0);  // the slings pull the hook down

  // 2. the hook: the hoist's 16 parts carry its weight and the slings' pull
  const double hoist =
      pullZ("FC.main_hoist", 16, "FC.hook", Eigen::Vector3d::Zero(), "FC.boom", {100, 0, 0});
  CHECK(hoist + onHook == Approx(mass("FC.hook") * kG).epsilon(1e-6));

  // 3. the floating crane and its hook displace their mass plus the slings' downward pull
  double crane = 0.0;
  for (int i = 1; i < m.nbodies; ++i)
    if (m.names[i].rfind("FC.", 0) == 0) crane += m.inertias[i].mass;
  REQUIRE(crane == Approx(7.5e6 + 2 * 2.0e6 + 2 * 1.0e5 + 6.0e5 + 1.1e6 + 8.0e4));
  INFO("displacement " << read("FC.hull.displacement") << " kg, crane " << crane
                       << " kg, slings' pull " << -onHook / kG << " kg");
  CHECK(read("FC.hull.displacement") == Approx(crane - onHook / kG).epsilon(1e-6));
}

TEST_CASE(
    "megablock with a floating crane: statics and action order and transport and peak over "
    "static",
    "[long]") {
  scene::ParamOverrides o;
  give(o, "haul_in", "-2.0");
  give(o, "travel", "10.0");
  give(o, "lower", "2.0");
  auto loaded = scene::loadScene(
      std::string(YARDSIM_SOURCE_DIR) + "/examples/megablock_floating_crane/scene.yaml", o);
  INFO(loaded.diagnostics.report());
  REQUIRE(loaded.scene);
  auto root = scene::assemble(*loaded.scene);
  devs::Simulator sim(*root);
  testing::RecordCollector rec(false);
  sim.addListener(rec);
  const auto& mb = static_cast<const models::MultibodyModel&>(*root->findComponent("mechanics"));
  const Reader read(mb);
  const dynamics::Model& m = mb.mechanics();
  auto mass = [&](const char* b) { return m.inertias[m.bodyIndex(b)].mass; };

  // 1. hanging still in static equilibrium before the hoists start: the goliath ropes (4 parts)
  // and the floating crane's hoist (16 parts) carry the block, its loader and the hook. Their
  // tensions' sum equals the weight up to the ropes' small inclinations (it cannot be less)
  sim.runUntil(4.0);
  const double hung = mass("block") + mass("loader_clamp") + mass("loader_beam") + mass("FC.hook");
  REQUIRE(hung == Approx(3.63e6));
  double sum = 16.0 * read("FC.main_hoist.tension");
  for (const char* r : kGoliath) sum += 4.0 * read(std::string(r) + ".tension");
  CHECK(sum >= hung * kG * (1 - 1e-9));
  CHECK(sum <= hung * kG * (1 + 1e-3));
  CHECK(mb.state().x.v.cwiseAbs().maxCoeff() < 1e-6);
  // the floating crane carries its share on the four slings; it floats at its displacement
  double slings = 0.0;
  for (const char* s : kSlings) slings += read(std::string(s) + ".tension");
  CHECK(slings > 16.0 * read("FC.main_hoist.tension") - mass("FC.hook") * kG);  // slings incline
  std::map<std::string, double> still;
  for (const auto& [name, c] : read.byName)
    if (name.size() > 8 && name.substr(name.size() - 8) == ".tension") still[name] = c.read();
  const double z0 = read("block.z"), x0 = read("block.x"),
               balance0 = read("mechanics.energy_balance");

  // 2. the action list: hoist 2 m, transport 10 m, hoist down 2 m
  // (each hoist drive ramps at a = 0.02 m/s^2: a trapezoid of d / v + v / a)
  const double ramp = 0.083 / 0.02;
  sim.runUntil(5.0 + 2.0 / 0.083 + ramp + 10.0 / 0.4 + 2.0 / 0.083 + ramp + 15.0);
  std::map<std::string, double> started, finished;
  for (const auto& r : rec.ofKind("out")) {
    if (r.port == "started") started[r.model] = r.t;
    if (r.port == "finished") finished[r.model] = r.t;
  }
  REQUIRE(finished.size() == 21);
  const double hoisted = 5.0 + 2.0 / 0.083 + ramp;
  for (int k = 1; k <= 9; ++k)
    CHECK(finished.at("hoist" + std::to_string(k)) == Approx(hoisted).margin(1e-6));
  double moved = 0.0;
  for (const char* a : {"travel1", "travel2", "travel3"}) {
    CHECK(started.at(a) == Approx(hoisted).margin(1e-9));
    CHECK(finished.at(a) == Approx(hoisted + 10.0 / 0.4).margin(3.0));
    moved = std::max(moved, finished.at(a));
  }
  for (int k = 1; k <= 9; ++k) {
    CHECK(started.at("lower" + std::to_string(k)) == Approx(moved).margin(1e-9));
    CHECK(finished.at("lower" + std::to_string(k)) ==
          Approx(moved + 2.0 / 0.083 + ramp).margin(1e-6));
  }

  // 3. the block has gone 10 m along +x with the cranes and is back at its height
  // (the travel servos yield to the swinging block: up to 5.2 mm in the full run, calm or not)
  CHECK(read("GOC201.travel.q") == Approx(10.0).margin(1e-2));
  CHECK(read("GOC202.travel.q") == Approx(10.0).margin(1e-2));
  CHECK(read("fc_travel.q") == Approx(10.0).margin(0.02));  // its servo yields to the tow force
  CHECK(read("block.z") - z0 == Approx(0.0).margin(0.1));
  // every rope is loaded above its static tension by the hoist starts, the transport, wind and
  // waves; peak over static within 1.0 .. 1.6 (stated in the README)
  for (const auto& [name, s] : still) {
    const std::string rope = name.substr(0, name.size() - 8);
    const double ratio = read(rope + ".peak_tension") / s;
    INFO(rope << " peak / static = " << ratio);
    CHECK(ratio > 1.0);
    CHECK(ratio < 1.6);
  }
  // the floating crane stays within a degree of heel and trim
  CHECK(std::abs(read("FC.hull.heel")) < M_PI / 180);
  CHECK(std::abs(read("FC.hull.trim")) < M_PI / 180);
  // energy: kinetic + potential - work of winches, drives, damping, wind and waves stays
  // constant, to a small fraction of the energy of lifting the hung mass 1 m
  CHECK(std::abs(read("mechanics.energy_balance") - balance0) < 1e-3 * hung * kG * 1.0);

  // 4. the block swings along x on its ~53 m ropes after the stop, with an amplitude of about
  // v / omega = 0.4 / sqrt(9.81 / 53) = 0.93 m, about the 10 m it was carried: over one period
  // (14.6 s) the middle of its range is 10 m from its start and the half range about v / omega
  double lo = 1e9, hi = -1e9;
  const double from = sim.time();
  for (double t = from + 0.1; t <= from + 14.6 + 1e-9; t += 0.1) {
    sim.runUntil(t);
    lo = std::min(lo, read("block.x") - x0);
    hi = std::max(hi, read("block.x") - x0);
  }
  INFO("block.x - x0 over one pendulum period: " << lo << " .. " << hi << " m");
  CHECK(0.5 * (lo + hi) == Approx(10.0).margin(0.3));
  CHECK(0.5 * (hi - lo) > 0.3);
  CHECK(0.5 * (hi - lo) < 1.5);
}

// The full operation in calm water: the block is carried over the dock gate (its top at z = 6 m,
// x = 40..44 m) between the dock's side walls (|y| >= 26 m) and set down on the two rows of dock
// blocks (tops at z = 0). The clearance watches' channels give the distances at every recorded
// instant; their minimum must stay positive (no `touched` event either), and at the end the block
// rests on the dock blocks beyond the gate, the contact carrying what the slackened ropes no longer
// do.
TEST_CASE(
    "megablock with a floating crane: the block clears the dock gate and sets down on the dock "
    "blocks",
    "[long]") {
  scene::ParamOverrides o;
  give(o, "sea", "[]");
  auto loaded = scene::loadScene(
      std::string(YARDSIM_SOURCE_DIR) + "/examples/megablock_floating_crane/scene.yaml", o);
  INFO(loaded.diagnostics.report());
  REQUIRE(loaded.scene);
  auto root = scene::assemble(*loaded.scene);
  devs::Simulator sim(*root);
  testing::RecordCollector rec(false);
  sim.addListener(rec);
  const auto& mb = static_cast<const models::MultibodyModel&>(*root->findComponent("mechanics"));
  const Reader read(mb);
  const dynamics::Model& m = mb.mechanics();
  const double block = m.inertias[m.bodyIndex("block")].mass;

  // (every 0.1 s of the operation) => the smallest clearances, and where the block was then
  double gate = 1e9, walls = 1e9, xAtGate = 0.0, firstContact = -1.0, z440 = 0.0;
  bool overGate = false;
  for (double t = 0.1; t <= 450.0 + 1e-9; t += 0.1) {
    sim.runUntil(t);
    const double g = read("gate.distance");
    if (g < gate) gate = g, xAtGate = read("block.x");
    walls = std::min({walls, read("wall_ps.distance"), read("wall_sb.distance")});
    // (the block's 48 m span along x straddles the gate's 40..44 m)
    const double x = read("block.x");
    if (x + 24.0 > 44.0 && x - 24.0 < 40.0) overGate = true;
    if (firstContact < 0.0 && read("collision.points") > 0.0) firstContact = t;
    if (std::abs(t - 440.0) < 1e-6) z440 = read("block.z");
  }
  INFO("minimum clearance to the gate " << gate << " m (block at x = " << xAtGate
                                        << " m), to the walls " << walls << " m, first contact at "
                                        << firstContact << " s");
  CHECK(overGate);
  CHECK(gate > 0.5);   // the gate's top 6 m, the hoisted block's bottom about 7.9 m
  CHECK(gate < 2.5);   // ... and the watch does measure the gate (not its 30 m range)
  CHECK(walls > 5.0);  // the walls 10 m beside the block's sides
  for (const auto& r : rec.ofKind("out")) CHECK(r.value.find("touched") == std::string::npos);
  // the block has passed the gate: its aft end beyond the gate's far face
  CHECK(read("block.x") - 24.0 > 44.0);
  // it touches down during the hoist-down and rests on the dock blocks (bottom at z = 0; the
  // penetration of four points of 2e9 N/m under at most its weight is below 5 mm)
  CHECK(firstContact > 302.0);
  CHECK(read("collision.points") >= 4.0);
  CHECK(read("block.z") == Approx(6.0).margin(0.01));
  CHECK(std::abs(read("block.z") - z440) < 1e-3);  // at rest
  // the dock blocks carry a share of the block's weight, never more than all of it
  const double fz = read("collision.block.fz");
  CHECK(fz > 0.1 * block * kG);
  CHECK(fz < block * kG * (1 + 1e-3));
  CHECK(read("collision.dock_block_fore.fz") + read("collision.dock_block_aft.fz") ==
        Approx(-fz).epsilon(1e-9));
}
