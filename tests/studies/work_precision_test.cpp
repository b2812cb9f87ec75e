// The work-precision machinery: error norms against closed forms, and the measured convergence
// order of each fixed-step method when the step halves (a mass bouncing on a taut rope).
#include "studies/work_precision.hpp"

#include <catch2/catch.hpp>
#include <cmath>

#include "scene/scene_loader.hpp"
#include "support/scene_files.hpp"
#include "support/test_paths.hpp"

using namespace yardsim;

namespace {
// A 10 t block bouncing on a rope (EA 2e8 N, 20 m: 31.6 rad/s), 5 mm about its static
// position (stretch 9.8 mm), so the rope stays taut and the solution is smooth.
const char* kBounce = R"(schema_version: 1
name: bounce
integrator: {method: rk4, dt: 0.01}
mechanics:
  bodies:
    block: {parent: world, joint: {type: prismatic, axis: [0, 0, 1], q0: -20.015}, mass: 1.0e4, inertia: [1, 1, 1]}
  ropes:
    rope: {path: [{body: world, point: [0, 0, 0]}, {body: block, point: [0, 0, 0]}], EA: 2.0e8, L0: 20.0}
until: 1
wp:
  channels: [block.z]
  interval: 0.02
  methods:
    - {method: rk4, dt0: 0.02, levels: 3}
    - {method: semi_implicit_euler, dt0: 0.005, levels: 3}
  reference: {method: rk4, dt: 0.0002}
  check: {method: semi_implicit_euler, dt: 0.00001}
  repeats: 1
)";

studies::WpSeries series(std::vector<std::vector<double>> v) {
  studies::WpSeries s;
  s.values = std::move(v);
  return s;
}
}  // namespace

TEST_CASE("error norms: Euclidean over channels, then final, rms and max over the grid") {
  const auto ref = series({{0, 0}, {0, 0}, {0, 0}, {0, 0}});
  const auto run = series({{0, 0}, {3, 4}, {0, 0}, {0, 1}});  // |e| = 0, 5, 0, 1
  const auto e = studies::errorNorms(run, ref);
  CHECK(e.final == Approx(1.0));
  CHECK(e.max == Approx(5.0));
  CHECK(e.rms == Approx(std::sqrt(26.0 / 4.0)));
  // a run that stopped early is measured over the times it reached
  CHECK(studies::errorNorms(series({{0, 0}, {3, 4}}), ref).final == Approx(5.0));
}

TEST_CASE("halving the step divides the error by 2^p: RK4 p = 4, semi-implicit Euler p = 1") {
  testing::SceneDir dir;
  auto scene = scene::loadSceneOrThrow(dir.write("bounce.yaml", kBounce));
  models::Diagnostics d;
  const studies::WpSpec spec = studies::parseWpSpec(*scene, d);
  REQUIRE_FALSE(d.hasErrors());
  const studies::WpResult r = studies::workPrecision(*scene, spec);
  REQUIRE(r.rows.size() == 6);
  CHECK(r.omegaMax == Approx(std::sqrt(2e8 / 20.0 / 1e4)).epsilon(1e-3));
  // the reference (RK4) and its check (a different method) agree far below the errors measured
  CHECK(r.referenceCheck.rms < 2e-6);
  for (const auto& row : r.rows) {
    CHECK(row.status == "ok");
    CHECK(row.omegaDt == Approx(r.omegaMax * row.run.dt));
    // the DTSS model computes its next step ahead: one step beyond the end
    const auto n = static_cast<std::uint64_t>(std::llround(1.0 / row.run.dt));
    CHECK((row.series.steps == n || row.series.steps == n + 1));
  }
  // right-hand-side evaluations per step: 4 for RK4, 1 for semi-implicit Euler
  CHECK(r.rows[0].series.fEvals >= 4 * r.rows[0].series.steps);
  CHECK(r.rows[3].series.fEvals >= r.rows[3].series.steps);
  CHECK(r.rows[3].series.fEvals < 2 * r.rows[3].series.steps);
  auto order = [&](std::size_t i) { return std::log2(r.rows[i].error.rms / r.rows[i + 1].error.rms); };
  INFO("rk4 orders " << order(0) << " " << order(1) << ", euler " << order(3) << " " << order(4));
  CHECK(order(1) == Approx(4.0).margin(0.3));
  CHECK(order(4) == Approx(1.0).margin(0.15));
}

TEST_CASE("a run that blows up is a row with status blow-up, not a failure of the sweep") {
  // the hook scene (omega_max 119 rad/s) with RK4 at 0.05 s: omega dt = 5.95 > 2.83
  auto scene = scene::loadSceneOrThrow(std::string(YARDSIM_SOURCE_DIR) + "/examples/stiff/hook_hoist_920t.yaml");
  models::Diagnostics d;
  studies::WpSpec spec = studies::parseWpSpec(*scene, d);
  REQUIRE_FALSE(d.hasErrors());
  spec.interval = 0.05;
  spec.until = 1.0;
  spec.reference = {"rk4", "rk4", 1e-3, 0.0, {}};
  spec.check = {"semi_implicit_euler", "semi_implicit_euler", 1e-4, 0.0, {}};
  spec.runs = {{"rk4", "rk4", 0.05, 0.0, {}}};
  const auto r = studies::workPrecision(*scene, spec);
  REQUIRE(r.rows.size() == 1);
  CHECK(r.rows[0].status == "blow-up");
  CHECK(r.rows[0].omegaDt == Approx(5.95).epsilon(0.01));
  CHECK(std::isinf(r.rows[0].error.rms));
}

TEST_CASE("an adaptive sweep: one run per tolerance, the integrator's own work counted, errors falling") {
  testing::SceneDir dir;
  auto scene = scene::loadSceneOrThrow(dir.write("bounce.yaml", kBounce));
  models::Diagnostics d;
  studies::WpSpec spec = studies::parseWpSpec(*scene, d);
  REQUIRE_FALSE(d.hasErrors());
  spec.runs = {{"bdf", "cvode_bdf", 0.0, 1e-4, {}}, {"bdf", "cvode_bdf", 0.0, 1e-7, {}}};
  const auto r = studies::workPrecision(*scene, spec);
  REQUIRE(r.rows.size() == 2);
  for (const auto& row : r.rows) {
    CHECK(row.status == "ok");
    CHECK(row.series.jacEvals > 0);
    CHECK(row.series.newtonIts > 0);
    CHECK(row.series.fEvals > row.series.steps);
    // omega_dt is omega_max times the mean internal step
    CHECK(row.omegaDt == Approx(r.omegaMax * 1.0 / static_cast<double>(row.series.steps)));
  }
  CHECK(r.rows[1].series.steps > r.rows[0].series.steps);
  CHECK(r.rows[1].error.rms < 0.1 * r.rows[0].error.rms);
  CHECK(r.rows[0].run.param() == "rtol=0.0001");
}
