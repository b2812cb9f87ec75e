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
#include "scene/scene_loader.hpp"
#include "support/csv_file.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;

namespace {

// 314 m of 120 mm studless chain: 282.21 kg/m in air, volume-equivalent diameter 0.216 m
// (2400 N/m in water), EA 1.2e9 N; the anchor on the bed at the origin, the fairlead 290 m away
// and 39 m up
constexpr double kMass = 282.21, kDiameter = 0.216, kRho = 1025.0, kG = 9.81;
double weight() { return (kMass - kRho * std::numbers::pi / 4.0 * kDiameter * kDiameter) * kG; }

// (segments, integrator, line keys, fairlead on a fixed post or on a slider with v0) => a scene
std::string hanging(int segments, const std::string& integrator, const std::string& extra = "",
                    const std::string& post = "joint: {type: fixed}", double until = 40.0) {
  return R"(schema_version: 1
integrator: )" + integrator +
         R"(
mechanics:
  gravity: [0, 0, -9.81]
  bodies:
    post:
      parent: world
      )" + post + R"(
      placement: {xyz: [290, 0, 39]}
      mass: 2.0e5
      inertia: [1, 1, 1]
  mooring:
    line: {model: lumped, anchor: [0, 0, 0], fairlead: {body: post, point: [0, 0, 0]},
           length: 314, EA: 1.2e9, mass: 282.21, diameter: 0.216, segments: )" +
         std::to_string(segments) + extra + R"(}
record: {interval: 0.1, channels: ["line.*", "post.*", "mechanics.energy_balance", "mechanics.work", "mechanics.energy"]}
until: )" + std::to_string(until) +
         "\n";
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

TEST_CASE("lumped line: at rest it reproduces the catenary fairlead tension and converges") {
  const forces::CatenaryParameters chain{314.0, 1.2e9, weight(), true, 0.0};
  const auto c = forces::solveCatenary(chain, 290.0, 39.0);
  REQUIRE(c.status == forces::CatenaryStatus::Converged);
  REQUIRE(c.profile == forces::CatenaryProfile::TouchingDown);
  const double exact = std::hypot(c.hf, c.vf);
  double previous = 0.0;
  for (int n : {5, 10, 20, 40}) {
    testing::SceneDir dir;
    const auto csv = simulate(dir, hanging(n, rk4For(n)), 40.0);
    const double t = meanFrom(csv, "line.fairlead_tension[N]", 30.0);
    const double err = std::abs(t / exact - 1.0);
    INFO(n << " segments: " << t << " N against " << exact << " N, error " << err);
    if (n == 20) CHECK(err < 0.01);
    if (previous > 0.0) CHECK(err < 0.6 * previous);  // converges: at least order 0.7 per doubling
    previous = err;
    // (laid length) => within two segments of the catenary's
    CHECK(std::abs(meanFrom(csv, "line.laid_length[m]", 30.0) - c.laidLength) < 2.0 * 314.0 / n);
  }
}

TEST_CASE("lumped line: the energy balance closes without dissipation and with it") {
  // (fairlead on a 200 t slider pulled away at 0.5 m/s) => the line swings and stretches
  const std::string slider = "joint: {type: prismatic, axis: [1, 0, 0], v0: 0.5}";
  const double kinetic0 = 0.5 * 2.0e5 * 0.25;  // J
  SECTION("no damping, no drag, no bed: only the integrator's error") {
    testing::SceneDir dir;
    const auto csv = simulate(
        dir,
        hanging(10, rk4For(10), ", damping: 0, cdn: 0, cdt: 0, seabed: false", slider, 20.0),
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
  SECTION("internal damping, drag and the bed with friction: the provider's power closes it") {
    testing::SceneDir dir;
    const auto csv =
        simulate(dir, hanging(10, rk4For(10), ", friction: 0.5", slider, 20.0), 20.0);
    const int b = csv.column("mechanics.energy_balance[J]"), w = csv.column("mechanics.work[J]");
    REQUIRE(b > 0);
    double drift = 0.0;
    for (const auto& r : csv.rows) drift = std::max(drift, std::abs(r[b] - csv.rows[0][b]));
    const double dissipated = -csv.rows.back()[w];
    INFO("dissipated " << dissipated << " J, largest drift " << drift << " J");
    CHECK(dissipated > 0.1 * kinetic0);
    CHECK(drift < 1e-3 * dissipated);
  }
}

TEST_CASE("lumped line: implicit methods step the nodes at 0.05 s and rest where RK4 does") {
  const forces::CatenaryParameters chain{314.0, 1.2e9, weight(), true, 0.0};
  const auto c = forces::solveCatenary(chain, 290.0, 39.0);
  const double exact = std::hypot(c.hf, c.vf);
  testing::SceneDir dirRk4;
  const double rk4 = meanFrom(simulate(dirRk4, hanging(20, rk4For(20)), 40.0),
                              "line.fairlead_tension[N]", 30.0);
  for (const std::string method : {"hht", "generalized_alpha", "cvode_bdf"}) {
    testing::SceneDir dir;
    const auto csv = simulate(dir, hanging(20, "{method: " + method + ", dt: 0.05}"), 40.0);
    const double t = meanFrom(csv, "line.fairlead_tension[N]", 30.0);
    INFO(method << ": " << t << " N, RK4 " << rk4 << " N, catenary " << exact << " N");
    CHECK(t == Approx(rk4).epsilon(1e-3));
  }
}

TEST_CASE("lumped line: the stiffness guard sees the highest axial mode of the segments") {
  for (int n : {10, 20}) {
    testing::SceneDir dir;
    auto scene = scene::loadSceneOrThrow(dir.write("s.yaml", hanging(n, rk4For(n))));
    REQUIRE(scene->systems.size() == 1);
    REQUIRE(scene->systems[0]->built);
    const auto e = mechanics::estimateStiffness(*scene->systems[0]->built);
    // (N - 1 masses m' between springs EA / l, both ends held) => 2 sqrt(EA / (l m')) sin(pi
    // (N - 1) / (2 N)), the highest axial mode of the chain
    const double l = 314.0 / n, m = (kMass + kRho * std::numbers::pi / 4.0 * kDiameter * kDiameter) * l;
    const double axial = 2.0 * std::sqrt(1.2e9 / l / m) * std::sin(std::numbers::pi * (n - 1) / (2.0 * n));
    INFO(n << " segments: omega_max " << e.omegaMax << " rad/s, axial " << axial << " rad/s, body '"
           << e.body << "', element '" << e.element << "'");
    CHECK(e.omegaMax == Approx(axial).epsilon(0.03));
    CHECK(e.body.rfind("line.node", 0) == 0);
    CHECK(e.element == "line");
  }
}
