// Bending stiffness `EI:` on lumped ropes and mooring lines
// (scene/providers/lumped_rope_reader.cpp, mooring_reader.cpp;
// forces/lines/lumped_line_bending.hpp), run through scenes: a taut rope with EI plucked by one end
// rings at the pinned-pinned tensioned beam's first frequency (1 / 2L) sqrt(H / m') sqrt(1 + pi^2
// EI / (H L^2)); the energy balance of a rope swinging with its bending closes at RK4's fourth
// order; the stiffness guard's omega_max is the discrete bending mode's (it rises as EI / l^4); EI:
// 0 is the rope without the key; bad values are reported at their YAML node with the key path.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <iomanip>
#include <numbers>
#include <sstream>
#include <string>

#include "mechanics/stiffness_estimate.hpp"
#include "run/runner.hpp"
#include "scene/assembler.hpp"
#include "scene/mechanical_systems.hpp"
#include "scene/scene_loader.hpp"
#include "support/csv_file.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;
using Catch::Matchers::Contains;

namespace {

// the rope: 10 kg/m, 40 mm, EA 5e7 N
constexpr double kMu = 10.0;
const std::string kRope = "EA: 5.0e7, mass_per_length: 10, diameter: 0.04";

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

// (span, unstretched length, segments, rope keys, the east post's joint keys after its slider
// along y, or "fixed", dt, components) => a rope between a fixed post at the origin and a post at
// x = span
std::string span(double x, double length, int segments, const std::string& extra,
                 const std::string& joint, double dt, const std::string& components = "") {
  std::ostringstream os;
  os << std::setprecision(17) << "schema_version: 1\nintegrator: {method: rk4, dt: " << dt << "}\n"
     << components << R"(mechanics:
  bodies:
    west: {parent: world, joint: {type: fixed}, mass: 1000, inertia: [1, 1, 1]}
    east:
      parent: world
      joint: )"
     << (joint == "fixed" ? "{type: fixed"
                          : "{name: slide, type: prismatic, axis: [0, 1, 0], " + joint)
     << R"(}
      placement: {xyz: [)"
     << x << R"(, 0, 0]}
      mass: 1000
      inertia: [1, 1, 1]
  ropes:
    span: {model: lumped, path: [{body: west, point: [0, 0, 0]}, {body: east, point: [0, 0, 0]}],
           L0: )"
     << length << ", segments: " << segments << ", " << kRope << extra << R"(}
record: {interval: 0.005, channels: ["span.*", "mechanics.energy_balance", "mechanics.work"]}
)";
  return os.str();
}

}  // namespace

TEST_CASE("rope with EI: plucked, it rings at the pinned-pinned tensioned beam's frequency") {
  // (50 m span, 49.9 m of rope: H about 1e5 N, EI 1.33e7 N m^2: pi^2 EI / (H L^2) ~ 0.5) =>
  // f1 = (1 / 2L) sqrt(H / m') sqrt(1 + pi^2 EI / (H L^2)), H the tension at rest (measured: the
  // bending carries part of the weight and changes the sag), m' the mass per metre of span; the
  // east post moves 5 cm across in 0.5 s and holds
  const double x = 50.0, L0 = 49.9, ei = 1.33e7;
  testing::SceneDir dir;
  const auto csv = simulate(
      dir,
      span(x, L0, 20, ", EI: 1.33e7", "hold: true", 0.0005,
           "components:\n  pluck: {type: joint_actor, params: {joint: slide, target: 0.05, speed: "
           "0.1, mode: prescribed, start_at: 0.5}}\n"),
      10.0);
  const double H = csv.rows.front()[col(csv, "span.max_tension[N]")];
  const double m = kMu * L0 / x, pi2 = std::numbers::pi * std::numbers::pi;
  const double string = std::sqrt(H / m) / (2.0 * x);
  const double f1 = string * std::sqrt(1.0 + pi2 * ei / (H * x * x));
  REQUIRE(H > 9e4);
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
  INFO("f1 " << measured << " Hz against " << f1 << " Hz (the string alone " << string << " Hz), H "
             << H << " N");
  CHECK(measured > 1.1 * string);
  CHECK(measured == Approx(f1).epsilon(0.02));
}

TEST_CASE("rope with EI: the energy balance closes at RK4's order while it swings and bends") {
  // (the east post, 1000 kg on its slider, set moving across at 0.5 m/s: the rope swings and
  // bends; no damping) => the balance drifts by RK4's error only, falling about 16 times per
  // halving of the step; the rope's energy (strain, bending, weight) swings by far more
  auto run = [](double dt) {
    testing::SceneDir dir;
    const auto csv =
        simulate(dir, span(10.0, 9.99, 10, ", EI: 2.0e4, damping: 0", "v0: 0.5", dt), 1.0);
    const int balance = col(csv, "mechanics.energy_balance[J]"), rope = col(csv, "span.energy[J]"),
              work = col(csv, "mechanics.work[J]");
    double drift = 0.0, swing = 0.0;
    for (const auto& r : csv.rows) {
      drift = std::max(drift, std::abs(r[balance] - csv.rows[0][balance]));
      swing = std::max(swing, std::abs(r[rope] - csv.rows[0][rope]));
    }
    return std::array<double, 3>{drift, swing, std::abs(csv.rows.back()[work] - csv.rows[0][work])};
  };
  const auto coarse = run(2e-4), fine = run(1e-4);
  INFO("drift " << coarse[0] << " J at 0.2 ms, " << fine[0] << " J at 0.1 ms, the rope's energy "
                << "swing " << fine[1] << " J, work " << fine[2] << " J");
  CHECK(fine[1] > 10.0);
  CHECK(fine[2] < 1e-9 * fine[1]);  // (nothing dissipates)
  CHECK(fine[0] < 1e-5 * fine[1]);
  CHECK(coarse[0] > 8.0 * fine[0]);
}

TEST_CASE("rope with EI: the stiffness guard sees the bending mode, which rises as EI / l^4") {
  // (10 m of rope across 10.01 m, 20 segments of l = 0.5 m, EI 2e7 N m^2: the zigzag bending
  // mode 4 sin^2(pi (N - 1) / 2N) sqrt(EI / (mu l^4)) over the highest axial mode 2 sqrt(EA /
  // (mu l^2)) sin(pi (N - 1) / 2N), by 2.5) => omega_max^2 = (T lambda / l + EI lambda^2 / l^3) /
  // (mu l), lambda = 4 sin^2(pi (N - 1) / 2N); and a quarter of it at twice the segment length
  for (int n : {10, 20}) {
    testing::SceneDir dir;
    auto scene = scene::loadSceneOrThrow(
        dir.write("s.yaml", span(10.01, 10.0, n, ", EI: 2.0e7", "fixed", 1e-5)));
    REQUIRE(scene->systems.size() == 1);
    REQUIRE(scene->systems[0]->built);
    const auto e = mechanics::estimateStiffness(*scene->systems[0]->built);
    const double l = 10.0 / n, T = 5e7 * 1e-3;
    const double s = std::sin(std::numbers::pi * (n - 1) / (2.0 * n)), lambda = 4.0 * s * s;
    const double bending =
        std::sqrt((T * lambda / l + 2e7 * lambda * lambda / (l * l * l)) / (kMu * l));
    const double axial = 2.0 * std::sqrt(5e7 / (kMu * l * l)) * s;
    INFO(n << " segments: omega_max " << e.omegaMax << " rad/s, bending " << bending
           << " rad/s, axial " << axial << " rad/s, body '" << e.body << "'");
    if (n == 20) CHECK(bending > 2.0 * axial);
    CHECK(e.omegaMax == Approx(bending).epsilon(0.03));
    CHECK(e.body.rfind("span.node", 0) == 0);
  }
}

TEST_CASE("rope with EI: 0 is the rope without the key, and problems are at their nodes") {
  // (EI: 0) => the same run, bit for bit, as without the key
  testing::SceneDir dir;
  const auto plain = simulate(dir, span(10.0, 9.99, 5, "", "v0: 0.5", 2e-4), 0.2);
  testing::SceneDir dir0;
  const auto zero = simulate(dir0, span(10.0, 9.99, 5, ", EI: 0", "v0: 0.5", 2e-4), 0.2);
  REQUIRE(plain.rows.size() == zero.rows.size());
  CHECK(plain.rows.back() == zero.rows.back());
  // (a negative EI on a rope, a NaN one on a lumped mooring line, EI on a catenary line and on a
  // massless rope) => each reported at its node with its key path
  const auto bad = scene::loadScene(dir.write("bad.yaml", R"(schema_version: 1
mechanics:
  bodies:
    top: {parent: world, joint: {type: fixed}, placement: {xyz: [0, 0, 30]}, mass: 1000, inertia: [1, 1, 1]}
    buoy: {parent: world, joint: {type: prismatic, axis: [1, 0, 0]}, mass: 1000, inertia: [1, 1, 1]}
  ropes:
    a: {model: lumped, path: [{body: top}, {body: buoy}], L0: 30, EA: 5e7, mass_per_length: 10, diameter: 0.04, EI: -1}
    b: {path: [{body: top}, {body: buoy}], L0: 30, EA: 5e7, EI: 1e4}
  mooring:
    c: {model: lumped, anchor: [100, 0, -50], fairlead: {body: buoy}, length: 120, EA: 1e9, mass: 100, diameter: 0.1, EI: .nan}
    d: {anchor: [-100, 0, -50], fairlead: {body: buoy}, length: 120, EA: 1e9, weight: 500, EI: 1e4}
)"));
  CHECK_FALSE(bad.scene);
  const std::string report = bad.diagnostics.report();
  INFO(report);
  CHECK_THAT(report, Contains("bad.yaml:7:") && Contains("a.EI") && Contains("must be >= 0"));
  CHECK_THAT(report, Contains("bad.yaml:8:") && Contains("unknown key 'EI'"));
  CHECK_THAT(report, Contains("bad.yaml:10:") && Contains("c.EI") && Contains("expected a number"));
  CHECK_THAT(report, Contains("bad.yaml:11:") && Contains("'EI' is a key of model: lumped"));
}
