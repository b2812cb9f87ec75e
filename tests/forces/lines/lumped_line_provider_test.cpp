// Lumped-mass lines whose inner nodes are bodies of the multibody system (`mooring:` with
// `model: lumped`), run through scenes: a chain hanging from a fixed fairlead onto the sea bed
// comes to rest at the elastic catenary's fairlead tension (closed form, forces/lines/catenary.hpp)
// within 1 % at 20 segments and converges as the segments double; the energy balance closes with
// every dissipation off (only the integrator's error) and with damping, drag and the bed on (the
// provider's power); implicit methods step the nodes at a step the explicit ones cannot take;
// the stiffness guard sees the segments' axial mode; a moored barge on four lumped lines comes
// to rest where the quasi-static catenary lines hold it.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <string>

#include "forces/lines/catenary.hpp"
#include "mechanics/stiffness_estimate.hpp"
#include "run/runner.hpp"
#include "scene/assembler.hpp"
#include "scene/mechanical_systems.hpp"
#include "scene/scene_loader.hpp"
#include "support/csv_file.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;

namespace {

// 314 m of 120 mm studless chain: 282.21 kg/m in air, volume-equivalent diameter 0.216 m
// (2400 N/m in water), EA 1.2e9 N; the anchor on the bed at the origin, the fairlead 300 m away
// and 39 m up (the moored barge's lines)
constexpr double kMass = 282.21, kDiameter = 0.216, kRho = 1025.0, kG = 9.81;
double weight() {
  return (kMass - kRho * std::numbers::pi / 4.0 * kDiameter * kDiameter) * kG;
}

// (segments, integrator, line keys, fairlead on a fixed post or on a slider with v0) => a scene
std::string hanging(int segments, const std::string& integrator, const std::string& extra = "",
                    const std::string& post = "joint: {type: fixed}", double until = 40.0) {
  return R"(schema_version: 1
integrator: )" +
         integrator +
         R"(
mechanics:
  gravity: [0, 0, -9.81]
  bodies:
    post:
      parent: world
      )" +
         post + R"(
      placement: {xyz: [300, 0, 39]}
      mass: 2.0e5
      inertia: [1, 1, 1]
  mooring:
    line: {model: lumped, anchor: [0, 0, 0], fairlead: {body: post, point: [0, 0, 0]},
           length: 314, EA: 1.2e9, mass: 282.21, diameter: 0.216, segments: )" +
         std::to_string(segments) + extra + R"(}
record: {interval: 0.1, channels: ["line.*", "post.*", "mechanics.energy_balance", "mechanics.work", "mechanics.energy"]}
until: )" +
         std::to_string(until) + "\n";
}

// (scene text) => its timeseries.csv after a run
testing::CsvFile simulate(const testing::SceneDir& dir, const std::string& text, double until) {
  auto scene = scene::loadSceneOrThrow(dir.write("s.yaml", text));
  auto root = scene::assemble(*scene);
  run::runScene(*scene, *root, {dir.path() / "out", until, {}, {}, 0.1});
  return testing::CsvFile((dir.path() / "out" / "timeseries.csv").string());
}

// (csv, column, from t) => the mean of the column from t on
double meanFrom(const testing::CsvFile& csv, const std::string& name, double t0) {
  const int k = csv.column(name);
  REQUIRE(k > 0);
  double sum = 0.0;
  int n = 0;
  for (const auto& r : csv.rows)
    if (r[0] >= t0) {
      sum += r[k];
      ++n;
    }
  REQUIRE(n > 0);
  return sum / n;
}

// (segments) => the RK4 step for the line's highest axial mode, 2 sqrt(EA / m') / l
std::string rk4For(int segments) {
  const double l = 314.0 / segments,
               m = kMass + kRho * std::numbers::pi / 4.0 * kDiameter * kDiameter;  // with Can = 1
  const double omega = 2.0 * std::sqrt(1.2e9 / m) / l;
  return "{method: rk4, dt: " + std::to_string(1.0 / omega) + "}";
}

}  // namespace

TEST_CASE("lumped line: at rest it reproduces the catenary fairlead tension and converges",
          "[long]") {
  const forces::CatenaryParameters chain{314.0, 1.2e9, weight(), true, 0.0};
  const auto c = forces::solveCatenary(chain, 300.0, 39.0);
  REQUIRE(c.status == forces::CatenaryStatus::Converged);
  REQUIRE(c.profile == forces::CatenaryProfile::TouchingDown);
  const double exact = std::hypot(c.hf, c.vf);
  double previous = 0.0;
  for (int n : {10, 20, 40, 80}) {
    testing::SceneDir dir;
    const auto csv = simulate(dir, hanging(n, rk4For(n), "", "joint: {type: fixed}", 2.0), 2.0);
    // (the run) => the line stays at rest: the tension of the first row is the last one's
    const int k = csv.column("line.fairlead_tension[N]");
    REQUIRE(k > 0);
    const double t = csv.rows.back()[k];
    CHECK(csv.rows.front()[k] == Approx(t).epsilon(1e-9));
    const double err = std::abs(t / exact - 1.0);
    INFO(n << " segments: " << t << " N against " << exact << " N, error " << err);
    // (20 segments of 15.7 m: about five of them hang, the touchdown falls between nodes)
    if (n == 20) CHECK(err < 0.015);
    if (n == 80) CHECK(err < 0.002);
    // (the touchdown moves between nodes as they refine: the error is not monotonic at 0.1 %)
    if (n == 20) previous = err;
    if (n > 20) CHECK(err < previous / 4.0);
    // (laid length) => within two segments of the catenary's
    CHECK(std::abs(csv.rows.back()[csv.column("line.laid_length[m]")] - c.laidLength) <
          2.0 * 314.0 / n);
  }
}

// (line keys, integrator, v0 of the buoy, until) => a 200 t buoy on a surge slider between two
// lumped lines whose anchors are 300 m either side on the bed, released at v0
std::string between(const std::string& extra, const std::string& integrator, double v0,
                    double until) {
  const std::string line =
      "length: 314, EA: 1.2e9, mass: 282.21, diameter: 0.216, segments: 10" + extra;
  return "schema_version: 1\nintegrator: " + integrator + R"(
mechanics:
  gravity: [0, 0, -9.81]
  bodies:
    buoy:
      parent: world
      joint: {type: prismatic, axis: [1, 0, 0], v0: )" +
         std::to_string(v0) + R"(}
      placement: {xyz: [0, 0, 39]}
      mass: 2.0e5
      inertia: [1, 1, 1]
  mooring:
    west: {model: lumped, anchor: [-300, 0, 0], fairlead: {body: buoy}, )" +
         line + R"(}
    east: {model: lumped, anchor: [300, 0, 0], fairlead: {body: buoy}, )" +
         line + R"(}
record: {interval: 0.1, channels: ["buoy.x", "west.*", "east.*", "mechanics.energy_balance", "mechanics.work", "mechanics.energy"]}
until: )" +
         std::to_string(until) + "\n";
}

TEST_CASE("lumped line: the energy balance closes without dissipation and with it", "[long]") {
  const double kinetic0 = 0.5 * 2.0e5 * 0.25;  // J: the buoy released at 0.5 m/s
  SECTION("no damping, no drag, no bed: only the integrator's error") {
    testing::SceneDir dir;
    const auto csv = simulate(dir,
                              between(", damping: 0, cdn: 0, cdt: 0, seabed: false",
                                      "{method: rk4, dt: 0.002}", 0.5, 20.0),
                              20.0);
    const int b = csv.column("mechanics.energy_balance[J]"), w = csv.column("mechanics.work[J]");
    REQUIRE(b > 0);
    double drift = 0.0;
    for (const auto& r : csv.rows) {
      drift = std::max(drift, std::abs(r[b] - csv.rows[0][b]));
      CHECK(std::abs(r[w]) < 1e-9 * kinetic0);  // nothing non-conservative does work
    }
    INFO("largest drift " << drift << " J of " << kinetic0 << " J kinetic at the start");
    CHECK(drift < 1e-4 * kinetic0);
  }
  SECTION("internal damping and drag: the provider's power closes it") {
    // (drift at dt and dt / 4) => falls with the step (first order: segments go slack and taut,
    // nodes touch the bed: forces that switch within a step): no power term is missing. The
    // bed's damping is off here: it jumps as a node touches the bed, which makes the error 100
    // times larger (424 J at 2 ms, 108 J at 0.5 ms of 16 kJ dissipated).
    double drifts[2], dissipated = 0.0;
    for (int k = 0; k < 2; ++k) {
      testing::SceneDir dir;
      const std::string rk4 = k == 0 ? "{method: rk4, dt: 0.002}" : "{method: rk4, dt: 0.0005}";
      const auto csv = simulate(dir, between(", bed_damping: 0", rk4, 0.5, 20.0), 20.0);
      const int b = csv.column("mechanics.energy_balance[J]"), w = csv.column("mechanics.work[J]");
      REQUIRE(b > 0);
      drifts[k] = 0.0;
      for (const auto& r : csv.rows)
        drifts[k] = std::max(drifts[k], std::abs(r[b] - csv.rows[0][b]));
      dissipated = -csv.rows.back()[w];
    }
    INFO("dissipated " << dissipated << " J, largest drift " << drifts[0] << " J at 2 ms, "
                       << drifts[1] << " J at 0.5 ms");
    CHECK(dissipated > 0.1 * kinetic0);
    CHECK(drifts[1] < 1e-3 * dissipated);
    CHECK(drifts[1] < drifts[0] / 3.0);
  }
}

TEST_CASE("lumped line: released off its rest the moored buoy settles back to it", "[long]") {
  testing::SceneDir rest, dir;
  const auto still =
      simulate(rest, between(", cdn: 2.4", "{method: hht, dt: 0.05}", 0.0, 1.0), 1.0);
  const auto csv =
      simulate(dir, between(", cdn: 2.4", "{method: hht, dt: 0.05}", 1.0, 300.0), 300.0);
  const int x = csv.column("buoy.x[m]"), t = csv.column("west.fairlead_tension[N]");
  REQUIRE(x > 0);
  double amplitude = 0.0, late = 0.0;
  for (const auto& r : csv.rows) {
    amplitude = std::max(amplitude, std::abs(r[x]));
    if (r[0] >= 250.0) late = std::max(late, std::abs(r[x]));
  }
  INFO("largest excursion " << amplitude << " m, after 250 s " << late << " m");
  CHECK(amplitude > 0.5);
  CHECK(late < 0.15 * amplitude);
  // (the buoy's last position) => the tension of the line at rest there, within its stiffness
  CHECK(std::abs(csv.rows.back()[t] - still.rows.back()[t]) < 0.1 * still.rows.back()[t]);
}

TEST_CASE("lumped line: implicit methods step the nodes at 0.05 s and rest where RK4 does",
          "[long]") {
  const forces::CatenaryParameters chain{314.0, 1.2e9, weight(), true, 0.0};
  const auto c = forces::solveCatenary(chain, 290.0, 39.0);
  const double exact = std::hypot(c.hf, c.vf);
  testing::SceneDir dirRk4;
  const double rk4 =
      meanFrom(simulate(dirRk4, hanging(20, rk4For(20)), 40.0), "line.fairlead_tension[N]", 30.0);
  for (const std::string method : {"hht", "generalized_alpha", "cvode_bdf"}) {
    testing::SceneDir dir;
    const auto csv = simulate(dir, hanging(20, "{method: " + method + ", dt: 0.05}"), 40.0);
    const double t = meanFrom(csv, "line.fairlead_tension[N]", 30.0);
    INFO(method << ": " << t << " N, RK4 " << rk4 << " N, catenary " << exact << " N");
    CHECK(t == Approx(rk4).epsilon(1e-3));
  }
}

TEST_CASE("lumped line: the stiffness guard sees the highest axial mode of the segments") {
  for (int n : {10, 20, 40}) {  // (no bed: its damping's real eigenvalue, 200 /s, would compete)
    testing::SceneDir dir;
    auto scene =
        scene::loadSceneOrThrow(dir.write("s.yaml", hanging(n, rk4For(n), ", seabed: false")));
    REQUIRE(scene->systems.size() == 1);
    REQUIRE(scene->systems[0]->built);
    const auto e = mechanics::estimateStiffness(*scene->systems[0]->built);
    // (N - 1 masses m' between springs EA / l, both ends held) => 2 sqrt(EA / (l m')) sin(pi
    // (N - 1) / (2 N)), the highest axial mode of the chain
    const double l = 314.0 / n,
                 m = (kMass + kRho * std::numbers::pi / 4.0 * kDiameter * kDiameter) * l;
    const double axial =
        2.0 * std::sqrt(1.2e9 / l / m) * std::sin(std::numbers::pi * (n - 1) / (2.0 * n));
    INFO(n << " segments: omega_max " << e.omegaMax << " rad/s, axial " << axial << " rad/s, body '"
           << e.body << "', element '" << e.element << "'");
    CHECK(e.omegaMax == Approx(axial).epsilon(0.03));
    CHECK(e.body.rfind("line.node", 0) == 0);
    CHECK(e.element.find("line") != std::string::npos);
  }
}
