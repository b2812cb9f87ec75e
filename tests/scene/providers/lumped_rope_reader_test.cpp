// `ropes:` with `model: lumped` (scene/providers/lumped_rope_reader.cpp): crane ropes with mass,
// run through scenes and checked against closed forms: a rope hanging a block at rest carries the
// block's weight plus its own at the top ((M + m' L) g) and the block's at the bottom (M g); a
// rope between two posts sags as the elastic catenary and converges at second order; the first
// transverse mode of a taut rope plucked by one end rings at (1 / 2L) sqrt(H / m'); the energy
// balance closes with and without internal damping; problems are reported at their YAML nodes.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <iomanip>
#include <numbers>
#include <sstream>
#include <string>

#include "forces/lines/catenary.hpp"
#include "run/runner.hpp"
#include "scene/assembler.hpp"
#include "scene/scene_loader.hpp"
#include "support/csv_file.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;
using Catch::Matchers::Contains;

namespace {

// the rope: 10 kg/m, 40 mm, EA 5e7 N; its weight per metre in air (the air's buoyancy 1.225 kg/m^3)
constexpr double kMu = 10.0, kD = 0.04, kEA = 5.0e7, kG = 9.81;
double weight() {
  return (kMu - 1.225 * std::numbers::pi / 4.0 * kD * kD) * kG;
}
const std::string kRope = "EA: 5.0e7, mass_per_length: 10, diameter: 0.04";

// (x) => x with every digit a double holds, for YAML
std::string num(double x) {
  std::ostringstream os;
  os << std::setprecision(17) << x;
  return os.str();
}

// (scene text, until) => its timeseries.csv after a run
testing::CsvFile simulate(const testing::SceneDir& dir, const std::string& text, double until) {
  auto scene = scene::loadSceneOrThrow(dir.write("s.yaml", text));
  auto root = scene::assemble(*scene);
  run::runScene(*scene, *root, {dir.path() / "out", until, {}, {}, 0.1});
  return testing::CsvFile((dir.path() / "out" / "timeseries.csv").string());
}

// (csv, column name) => its index, required
int col(const testing::CsvFile& csv, const std::string& name) {
  const int k = csv.column(name);
  INFO(name);
  REQUIRE(k > 0);
  return k;
}

// (block mass, rope length, segments, offset of the block below its rest, rope keys) => a block
// on a vertical slider hanging from a fixed top at z = 30 by a lumped rope
std::string hanging(double mass, double length, int segments, double below,
                    const std::string& extra = "", double dt = 0.0005) {
  // (static stretch of a rope hanging a mass, with its own weight) => the block's rest height
  const double stretch = (mass * kG * length + 0.5 * weight() * length * length) / kEA;
  const double z = 30.0 - length - stretch - below;
  return "schema_version: 1\nintegrator: {method: rk4, dt: " + num(dt) + R"(}
mechanics:
  bodies:
    top: {parent: world, joint: {type: fixed}, placement: {xyz: [0, 0, 30]}, mass: 1000, inertia: [1, 1, 1]}
    block:
      parent: world
      joint: {name: lift, type: prismatic, axis: [0, 0, 1], q0: )" +
         num(z) + R"(}
      mass: )" +
         std::to_string(mass) +
         R"(
      inertia: [100, 100, 100]
  ropes:
    hoist: {model: lumped, path: [{body: top, point: [0, 0, 0]}, {body: block, point: [0, 0, 0]}],
            L0: )" +
         std::to_string(length) + ", segments: " + std::to_string(segments) + ", " + kRope + extra +
         R"(}
record: {interval: 0.01, channels: ["hoist.*", "lift.q", "mechanics.energy_balance", "mechanics.work"]}
)";
}

// (span, unstretched length, segments, extra components) => a rope between a fixed post at the
// origin and a post at x = span, on a slider along y that a joint actor may move
std::string span(double x, double length, int segments, const std::string& components = "") {
  return R"(schema_version: 1
integrator: {method: rk4, dt: 0.0005}
)" + components +
         R"(mechanics:
  bodies:
    west: {parent: world, joint: {type: fixed}, mass: 1000, inertia: [1, 1, 1]}
    east:
      parent: world
      joint: {name: slide, type: prismatic, axis: [0, 1, 0], hold: true}
      placement: {xyz: [)" +
         std::to_string(x) + R"(, 0, 0]}
      mass: 1000
      inertia: [1, 1, 1]
  ropes:
    span: {model: lumped, path: [{body: west, point: [0, 0, 0]}, {body: east, point: [0, 0, 0]}],
           L0: )" +
         std::to_string(length) + ", segments: " + std::to_string(segments) + ", " + kRope +
         R"(}
record: {interval: 0.005, channels: ["span.*", "slide.q"]}
)";
}

}  // namespace

TEST_CASE(
    "lumped rope: a hanging block at rest - the top carries (M + m' L) g and the bottom M g") {
  const double M = 2000.0, L = 20.0;
  for (int n : {1, 4, 10}) {
    testing::SceneDir dir;
    const auto csv = simulate(dir, hanging(M, L, n, 0.0), 0.5);
    const int top = col(csv, "hoist.first_tension[N]"), bottom = col(csv, "hoist.last_tension[N]"),
              len = col(csv, "hoist.length[m]");
    INFO(n << " segments");
    // (exact for any number of segments: the end forces carry the half segments' weight)
    for (const auto* r : {&csv.rows.front(), &csv.rows.back()}) {
      CHECK((*r)[top] == Approx((M * kG + weight() * L)).epsilon(1e-6));
      CHECK((*r)[bottom] == Approx(M * kG).epsilon(1e-6));
      CHECK((*r)[len] == Approx(L + (M * kG * L + 0.5 * weight() * L * L) / kEA).epsilon(1e-9));
    }
  }
}

TEST_CASE("lumped rope: between two posts it sags as the elastic catenary and converges") {
  const forces::CatenaryParameters rope{101.0, kEA, weight(), false, 0.0};
  const auto c = forces::solveCatenary(rope, 100.0, 0.0);
  REQUIRE(c.status == forces::CatenaryStatus::Converged);
  const double sag = -forces::catenaryPoint(rope, c, 100.0, 50.5).z;  // at mid length
  const double end = std::hypot(c.ha, c.va);
  REQUIRE(sag > 5.0);
  double previous = 1.0;
  for (int n : {10, 20, 40}) {
    testing::SceneDir dir;
    const auto csv = simulate(dir, span(100.0, 101.0, n), 0.2);
    const auto& r = csv.rows.back();
    const double mid = -r[col(csv, "span.node" + std::to_string(n / 2) + ".z[m]")];
    const double tension = r[col(csv, "span.first_tension[N]")];
    const double err = std::max(std::abs(mid / sag - 1.0), std::abs(tension / end - 1.0));
    INFO(n << " segments: sag " << mid << " m against " << sag << " m, end tension " << tension
           << " N against " << end << " N");
    CHECK(r[col(csv, "span.last_tension[N]")] == Approx(tension).epsilon(1e-9));  // symmetric
    CHECK(csv.rows.front()[col(csv, "span.first_tension[N]")] == Approx(tension).epsilon(1e-9));
    if (n == 40) CHECK(err < 2e-3);
    CHECK(err < previous / 3.0);  // (second order: a quarter per halving)
    previous = err;
  }
}

TEST_CASE("lumped rope: a taut rope plucked by one end rings at its first transverse frequency") {
  // (50 m span, 49.9 m of rope: H about 1e5 N) => f1 = (1 / 2 span) sqrt(H / m'), m' the mass per
  // metre of span; the east post moves 5 cm across in 0.5 s (about half a period) and holds
  const double x = 50.0, L0 = 49.9;
  const forces::CatenaryParameters rope{L0, kEA, weight(), false, 0.0};
  const auto c = forces::solveCatenary(rope, x, 0.0);
  REQUIRE(c.status == forces::CatenaryStatus::Converged);
  const double f1 = std::sqrt(c.hf / (kMu * L0 / x)) / (2.0 * x);
  REQUIRE(f1 > 0.8);
  REQUIRE(f1 < 1.2);
  testing::SceneDir dir;
  const auto csv = simulate(
      dir,
      span(x, L0, 20,
           "components:\n  pluck: {type: joint_actor, params: {joint: slide, target: 0.05, speed: "
           "0.1, mode: prescribed, start_at: 0.5}}\n"),
      10.0);
  const int y = col(csv, "span.node10.y[m]");
  // (upward crossings of the mid node through its new rest, y = 0.025, after the pluck)
  std::vector<double> up;
  for (std::size_t k = 1; k < csv.rows.size(); ++k) {
    const double t = csv.rows[k][0], a = csv.rows[k - 1][y] - 0.025, b = csv.rows[k][y] - 0.025;
    if (t > 1.5 && a < 0 && b >= 0)
      up.push_back(csv.rows[k - 1][0] + (t - csv.rows[k - 1][0]) * -a / (b - a));
  }
  REQUIRE(up.size() >= 6);
  const double measured = static_cast<double>(up.size() - 1) / (up.back() - up.front());
  INFO("f1 " << measured << " Hz against " << f1 << " Hz, H " << c.hf << " N");
  CHECK(measured == Approx(f1).epsilon(0.02));
}

TEST_CASE("lumped rope: the energy balance closes - undamped and with internal damping") {
  // (a block released 2 cm below its rest: it bounces on the rope) => undamped, the balance's
  // drift is RK4's and falls at fourth order with the step (the axial modes of 2 m segments are
  // at omega dt = 0.2 to 0.5); damped, it stays a small fraction of the work the damping took
  auto run = [](const std::string& extra, double dt) {
    testing::SceneDir dir;
    const auto csv = simulate(dir, hanging(2000.0, 20.0, 10, 0.02, extra, dt), 1.0);
    const int balance = col(csv, "mechanics.energy_balance[J]"), rope = col(csv, "hoist.energy[J]"),
              work = col(csv, "mechanics.work[J]");
    double drift = 0.0, swing = 0.0;
    for (const auto& r : csv.rows) {
      drift = std::max(drift, std::abs(r[balance] - csv.rows[0][balance]));
      swing = std::max(swing, std::abs(r[rope] - csv.rows[0][rope]));
    }
    return std::array<double, 3>{drift, swing, std::abs(csv.rows.back()[work] - csv.rows[0][work])};
  };
  const auto coarse = run(", damping: 0", 2e-4), fine = run(", damping: 0", 1e-4);
  INFO("undamped: drift " << coarse[0] << " J at 0.2 ms, " << fine[0] << " J at 0.1 ms, the rope's "
                          << "energy swing " << fine[1] << " J, work " << fine[2] << " J");
  CHECK(fine[1] > 500.0);
  CHECK(fine[2] < 1e-9 * fine[1]);  // (nothing dissipates)
  CHECK(fine[0] < 5e-4 * fine[1]);
  CHECK(coarse[0] > 8.0 * fine[0]);
  const auto damped = run(", damping_ratio: 0.5", 1e-4);
  INFO("damped: drift " << damped[0] << " J, dissipated " << damped[2] << " J");
  CHECK(damped[2] > 50.0);
  CHECK(damped[0] < 5e-3 * damped[2]);
}

TEST_CASE("lumped rope: a wire actor hoists a block - static levels, damping, energy balance") {
  // (2 t block on 20 m of rope, 10 segments, hauled in 6 m at 1 m/s with an S-curve drive:
  // 0.5 m/s^2, 0.25 m/s^3, so 4 s up to speed (2 m), 2 s at speed, 4 s down; from t = 0.5 s)
  const double M = 2000.0, L = 20.0, w = weight();
  std::string text = hanging(M, L, 10, 0.0);
  text.insert(text.find("mechanics:"),
              "components:\n  up: {type: wire_actor, params: {rope: hoist, payout: -6, speed: 1, "
              "accel: 0.5, jerk: 0.25, start_at: 0.5}}\n");
  testing::SceneDir dir;
  const auto csv = simulate(dir, text, 12.5);
  const int top = col(csv, "hoist.first_tension[N]"),
            length = col(csv, "hoist.unstretched_length[m]"), z = col(csv, "lift.q[m]"),
            stretched = col(csv, "hoist.length[m]"),
            balance = col(csv, "mechanics.energy_balance[J]"), work = col(csv, "mechanics.work[J]");
  // (rows in [a, b], (row) => a value) => its mean
  auto mean = [&](double a, double b, auto&& of) {
    double sum = 0.0;
    int rows = 0;
    for (const auto& r : csv.rows)
      if (r[0] >= a && r[0] <= b) {
        sum += of(r);
        ++rows;
      }
    REQUIRE(rows > 50);
    return sum / rows;
  };
  // (row) => the static stretch of L(t) hanging the block, (M g L + w L^2 / 2) / EA
  auto stretch = [&](const std::vector<double>& r) {
    return (M * kG * r[length] + 0.5 * w * r[length] * r[length]) / kEA;
  };
  const double L1 = L - 6.0;
  CHECK(csv.rows.back()[length] == Approx(L1).epsilon(1e-12));
  // (at rest after the hoist, over about 6 bounce periods) => the top force (M + m' L1) g and the
  // block at 30 m less the stretched rope
  const double rest = mean(11.5, 12.5, [&](const auto& r) { return r[top]; });
  const double height = mean(11.5, 12.5, [&](const auto& r) { return r[z]; });
  INFO("top " << rest << " N against " << M * kG + w * L1 << " N");
  CHECK(rest == Approx(M * kG + w * L1).epsilon(1e-4));
  CHECK(height == Approx(30.0 - L1 - (M * kG * L1 + 0.5 * w * L1 * L1) / kEA).margin(2e-5));
  // (at the drive's speed) => the top force is quasi-static, and the damping acts on the
  // elongation beyond the payout: the rope keeps its static stretch (a damping on the raw strain
  // rate, c l'/l per segment, would stretch it about 7 % more while hauling in)
  const double cruise = mean(5.0, 6.4, [&](const auto& r) { return r[top]; });
  const double quasi = mean(5.0, 6.4, [&](const auto& r) { return M * kG + w * r[length]; });
  const double extra =
      mean(5.0, 6.4, [&](const auto& r) { return r[stretched] - r[length] - stretch(r); });
  const double usual = mean(5.0, 6.4, stretch);
  INFO("cruising: top " << cruise << " N against " << quasi << " N; stretch beyond the static "
                        << extra << " m of " << usual << " m");
  CHECK(cruise == Approx(quasi).epsilon(1e-3));
  CHECK(std::abs(extra) < 0.01 * usual);
  // (the winch's work: the block's rise M g 6 m, less the weight of the rope it takes in, which
  // leaves the model at its height) => the balance closes
  double drift = 0.0;
  for (const auto& r : csv.rows)
    drift = std::max(drift, std::abs(r[balance] - csv.rows[0][balance]));
  const double done = std::abs(csv.rows.back()[work] - csv.rows[0][work]);
  INFO("balance drift " << drift << " J, work " << done << " J");
  CHECK(done > 0.8 * M * kG * 6.0);
  CHECK(drift < 1e-7 * done);
}

TEST_CASE(
    "lumped rope: over a sheave at rest the ends differ from the sheave by the rope between") {
  // (anchor 20 m below a sheave, the rope up over it and down to a 2 t block on a slider with a
  // damper; the block placed at the continuous rope's rest) => at rest the block end carries M g,
  // the sheave T_S = M g + w u_B (u_B the unstretched rope below the sheave on the block side),
  // and each end's tension is T_S less the weight of the rope between it and the sheave: together
  // 2 T_S - first - last = w L0, the whole rope's weight
  const double M = 2000.0, L0 = 40.0, w = weight();
  const double lamA = std::hypot(0.5, 20.0);
  double uA = 20.0;  // (span A's unstretched length: its stretch under T_S falling by w per metre)
  for (int it = 0; it < 50; ++it) {
    const double ts = M * kG + w * (L0 - uA);
    const double f = uA + (ts * uA - 0.5 * w * uA * uA) / kEA - lamA;
    uA -= f / (1.0 + (ts - 2.0 * w * uA) / kEA);
  }
  const double uB = L0 - uA, lamB = uB + (M * kG * uB + 0.5 * w * uB * uB) / kEA;
  const double ts = M * kG + w * uB;
  testing::SceneDir dir;
  const auto csv = simulate(dir,
                            R"(schema_version: 1
integrator: {method: rk4, dt: 0.0002}
mechanics:
  bodies:
    head: {parent: world, joint: {type: fixed}, placement: {xyz: [0, 0, 30]}, mass: 1000, inertia: [1, 1, 1]}
    anchor: {parent: world, joint: {type: fixed}, placement: {xyz: [-0.5, 0, 10]}, mass: 1000, inertia: [1, 1, 1]}
    block: {parent: world, joint: {name: lift, type: prismatic, axis: [0, 0, 1], q0: )" +
                                num(30.0 - std::sqrt(lamB * lamB - 0.25)) + R"(},
            placement: {xyz: [0.5, 0, 0]}, mass: 2000, inertia: [100, 100, 100]}
  ropes:
    hoist: {model: lumped, path: [{body: anchor}, {body: head}, {body: block}], L0: 40, segments: 21, )" +
                                kRope + R"(}
  joint_springs:
    brake: {body: block, coordinate: 0, k: 0, c: 5.0e4}
record: {interval: 0.05, channels: ["hoist.*", "lift.q", "mechanics.energy_balance", "mechanics.work"]}
)",
                            10.0);
  const auto& r = csv.rows.back();
  const double first = r[col(csv, "hoist.first_tension[N]")],
               last = r[col(csv, "hoist.last_tension[N]")],
               sheave = r[col(csv, "hoist.sheave_tension[N]")];
  INFO("first " << first << " N, last " << last << " N, sheave " << sheave << " N against " << ts
                << " N; rope weight " << w * L0 << " N");
  CHECK(last == Approx(M * kG).epsilon(1e-3));
  CHECK(sheave == Approx(ts).epsilon(1e-3));
  CHECK(2.0 * sheave - first - last == Approx(w * L0).epsilon(2e-3));
  CHECK(r[col(csv, "hoist.max_tension[N]")] == Approx(sheave).epsilon(1e-9));
  // (the nodes next to the sheave and both spans' nodes are bodies)
  CHECK(csv.column("hoist.a.node1.z[m]") > 0);
  CHECK(csv.column("hoist.b.node1.z[m]") > 0);
  // (energy balance: the brake's and the rope's damping are the work)
  const int balance = col(csv, "mechanics.energy_balance[J]"), work = col(csv, "mechanics.work[J]");
  double drift = 0.0;
  for (const auto& row : csv.rows)
    drift = std::max(drift, std::abs(row[balance] - csv.rows[0][balance]));
  INFO("balance drift " << drift << " J, work " << r[work] << " J");
  CHECK(std::abs(r[work]) > 1.0);
  CHECK(drift < 1e-4 * std::abs(r[work]));
}

TEST_CASE("lumped rope: problems at their nodes") {
  testing::SceneDir dir;
  std::string text = hanging(2000.0, 20.0, 10, 0.0);
  text +=
      R"(    a: {model: lumped, path: [{body: top}, {body: block}], L0: 20, EA: 5e7, diameter: 0.04, mass_per_lenght: 10}
    b: {model: lumped, path: [{body: top}, {body: block}], L0: 20, EA: 5e7, diameter: 0.04, mass_per_length: 10, segments: 2.5, parts: 2, mbl: 1e6, min_length: 50}
    c: {model: lumped, path: [{body: top}, {body: block}], L0: -1, EA: 5e7, diameter: 0.04, mass_per_length: 10, damping: 1, damping_ratio: 0.2}
    d: {model: heavy, path: [{body: top}, {body: block}], L0: 20, EA: 5e7}
)";
  // (the ropes block is the last key of mechanics: the entries above join it)
  const auto at = text.find("record:");
  std::string moved = text.substr(0, at);
  const auto extra = text.substr(text.find("    a: {model"));
  moved += extra + text.substr(at, text.find("    a: {model") - at);
  const auto bad = scene::loadScene(dir.write("bad.yaml", moved));
  CHECK_FALSE(bad.scene);
  const std::string report = bad.diagnostics.report();
  INFO(report);
  CHECK_THAT(report, Contains("bad.yaml:") && Contains("mass_per_lenght") &&
                         Contains("mass_per_length") && Contains("whole number of segments") &&
                         Contains("one part") && Contains("'mbl' is a key of the massless rope") &&
                         Contains("L0 must be > 0") && Contains("either damping") &&
                         Contains("min_length must be > 0 and <= L0") &&
                         Contains("expected massless (the default) or lumped, got 'heavy'"));
  // (a body that is not there) => found when the fragments are merged, with did you mean
  const auto typo = scene::loadScene(dir.write("typo.yaml", R"(schema_version: 1
mechanics:
  bodies:
    top: {parent: world, joint: {type: fixed}, mass: 1000, inertia: [1, 1, 1]}
    block: {parent: world, joint: {type: prismatic, axis: [0, 0, 1]}, mass: 2000, inertia: [1, 1, 1]}
  ropes:
    e: {model: lumped, path: [{body: top}, {body: blok}], L0: 20, EA: 5e7, diameter: 0.04, mass_per_length: 10}
)"));
  CHECK_FALSE(typo.scene);
  // (a wire actor on a lumped rope over a sheave) => refused at the door: no winch there
  std::string winch = hanging(2000.0, 20.0, 10, 0.0);
  const std::string first = "{body: top, point: [0, 0, 0]}";
  winch.replace(winch.find(first), first.size(), "{body: top, point: [-1, 0, 0]}, " + first);
  winch.insert(winch.find("mechanics:"),
               "components:\n  lower: {type: wire_actor, params: {rope: "
               "hoist, payout: 1, speed: 0.1, start_at: 0}}\n");
  const auto wired = scene::loadScene(dir.write("winch.yaml", winch));
  CHECK_FALSE(wired.scene);
  CHECK_THAT(wired.diagnostics.report(),
             Contains("winch.yaml:") && Contains("has model: lumped over a sheave, which has no "
                                                 "winch"));
  CHECK_THAT(typo.diagnostics.report(), Contains("typo.yaml:7:") &&
                                            Contains("unknown body 'blok'") &&
                                            Contains("did you mean 'block'"));
}
