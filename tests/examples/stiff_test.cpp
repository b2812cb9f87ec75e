// The stiff and extreme suite (examples/stiff/, issue 6): what the guard predicts happens, each
// method converges at its order on the non-stiff block, the slack rope never pushes and its
// snap converges to the energy closed form, the 1e6 mass ratio is refused at a careless step and
// runs at the suggested one, and an hour of simulated time keeps a bounded energy error.
#include <catch2/catch.hpp>
#include <cmath>

#include "mechanics/build.hpp"
#include "devs/simulator.hpp"
#include "scene/assembler.hpp"
#include "scene/mechanical_systems.hpp"
#include "mechanics/stiffness_estimate.hpp"
#include "models/numerical_error.hpp"
#include "run/runner.hpp"
#include "scene/scene_loader.hpp"
#include "scene/stiffness_guard.hpp"
#include "studies/work_precision.hpp"
#include "support/csv_file.hpp"
#include "support/record_collector.hpp"
#include "support/scene_files.hpp"
#include "support/test_paths.hpp"

using namespace yardsim;

namespace {

std::string example(const std::string& name) {
  return std::string(YARDSIM_SOURCE_DIR) + "/examples/stiff/" + name + ".yaml";
}

struct Outcome {
  bool ok = true;
  std::string failure;
  double tEnd = 0.0;
};

// (scene, method, step, end time, output folder) => the run, or the numerical failure
Outcome runCase(scene::Scene& scene, const std::string& method, double dt, double until,
            const std::filesystem::path& out) {
  scene.integrator = method;
  scene.dt = dt;
  auto root = scene::assemble(scene);
  Outcome o;
  try {
    o.tEnd = run::runScene(scene, *root, {out, until, {}, {}, 0.1}).tEnd;
  } catch (const models::NumericalError& e) {
    o.ok = false;
    o.failure = e.what();
  }
  return o;
}

// (output folder, column) => the smallest recorded value
double smallest(const std::filesystem::path& out, const std::string& column) {
  const testing::CsvFile csv((out / "timeseries.csv").string());
  const int c = csv.column(column);
  REQUIRE(c > 0);
  double m = HUGE_VAL;
  for (const auto& row : csv.rows) m = std::min(m, row[c]);
  return m;
}

mechanics::StiffnessEstimate estimateOf(const scene::Scene& scene) {
  return mechanics::estimateStiffness(mechanics::buildMechanics(scene.systems.at(0)->spec));
}

}  // namespace

TEST_CASE("920 t block on four slings: not stiff, every fixed-step method converges at its order") {
  auto scene = scene::loadSceneOrThrow(example("block_920t"));
  CHECK(estimateOf(*scene).omegaMax < 12.0);  // the slowest of the suite: ~9.4 rad/s
  models::Diagnostics d;
  studies::WpSpec spec = studies::parseWpSpec(*scene, d);
  REQUIRE_FALSE(d.hasErrors());
  // a short sweep: 2 s on a 0.1 s grid; each method at two steps in its asymptotic range
  spec.until = 2.0;
  spec.interval = 0.1;
  spec.repeats = 1;
  spec.reference = {"rk4", "rk4", 0.0005, 0.0, {}};
  spec.check = {"cvode_adams", "cvode_adams", 0.0, 1e-11, YAML::Load("{atol: 1.0e-12}")};
  struct Case {
    const char* method;
    double dt;
    double order;
  };
  const Case cases[] = {{"explicit_euler", 0.0025, 1}, {"semi_implicit_euler", 0.005, 1}, {"rk4", 0.05, 4},
                        {"ab2", 0.005, 2},             {"ab3", 0.01, 3},                 {"ab4", 0.01, 4},
                        {"hht", 0.01, 2},              {"generalized_alpha", 0.01, 2}};
  spec.runs.clear();
  for (const Case& c : cases)
    for (double f : {1.0, 0.5}) spec.runs.push_back({c.method, c.method, c.dt * f, 0.0, YAML::Node()});
  const auto r = studies::workPrecision(*scene, spec);
  CHECK(r.referenceCheck.rms < 1e-8);
  for (std::size_t i = 0; i < std::size(cases); ++i) {
    const auto& coarse = r.rows[2 * i];
    const auto& fine = r.rows[2 * i + 1];
    const double p = std::log2(coarse.error.rms / fine.error.rms);
    INFO(cases[i].method << ": E_rms " << coarse.error.rms << " -> " << fine.error.rms << ", order " << p);
    CHECK(coarse.status == "ok");
    CHECK(fine.status == "ok");
    CHECK(fine.error.rms > 30 * r.referenceCheck.rms);  // measurable against the reference
    CHECK(p == Approx(cases[i].order).margin(cases[i].order >= 4 ? 0.4 : 0.25));
  }
}

TEST_CASE("hook on a 16-part hoist over slings holding 920 t: omega_max 119 rad/s, RK4 stable at 0.0125 s, "
          "blowing up at 0.05 s, the guard predicts both") {
  auto scene = scene::loadSceneOrThrow(example("hook_hoist_920t"));
  const auto e = estimateOf(*scene);
  CHECK(e.omegaMax == Approx(119.0).epsilon(0.01));
  CHECK(mechanics::judgeStep(e, "rk4", 0.0125).stable);
  CHECK_FALSE(mechanics::judgeStep(e, "rk4", 0.05).stable);
  testing::SceneDir dir;
  const Outcome fine = runCase(*scene, "rk4", 0.0125, 5.0, dir.path() / "a");
  CHECK(fine.ok);
  CHECK(fine.tEnd == Approx(5.0));
  const Outcome blown = runCase(*scene, "rk4", 0.05, 5.0, dir.path() / "b");
  CHECK_FALSE(blown.ok);
  CHECK_THAT(blown.failure, Catch::Contains("hook"));
  // the limit is where the guard puts it: just inside 2.83 / omega_max the slings stay taut
  // (static 2.26 MN); just outside, the hook's mode grows until they go slack (a tension-only
  // rope bounds the growth, so the run may not stop, but its answer is wrong)
  const double limit = 2.0 * std::sqrt(2.0) / e.omegaMax;
  scene->record.interval = 0.95 * limit;
  REQUIRE(runCase(*scene, "rk4", 0.95 * limit, 5.0, dir.path() / "c").ok);
  CHECK(smallest(dir.path() / "c", "sling1.tension[N]") > 1e6);
  scene->record.interval = 1.1 * limit;
  // (just past the limit) => either the slings go slack (the answer is wrong: why the guard
  // matters) or the run stops with the diagnosis; both outcomes are checked
  const Outcome past = runCase(*scene, "rk4", 1.1 * limit, 5.0, dir.path() / "d");
  if (past.ok) CHECK(smallest(dir.path() / "d", "sling1.tension[N]") == 0.0);
  else CHECK_THAT(past.failure, Catch::Contains("hook") && Catch::Contains("suggestion"));
}

TEST_CASE(
    "3500 t block under a lumped 24-part hoist: omega_max ~1.4e3 rad/s, RK4 needs dt <= ~2 ms",
    "[long]") {
  auto scene = scene::loadSceneOrThrow(example("block_3500t"));
  const auto e = estimateOf(*scene);
  CHECK(e.omegaMax == Approx(1.4e3).epsilon(0.02));
  const double limit = 2.0 * std::sqrt(2.0) / e.omegaMax;
  CHECK(limit == Approx(2.0e-3).epsilon(0.03));
  testing::SceneDir dir;
  // inside the limit the hoist stays taut (static 1.46 MN per part); just outside, its lumped
  // nodes' mode grows until segments go slack; at twice the limit the run stops at once
  scene->record.interval = 0.9 * limit;
  REQUIRE(runCase(*scene, "rk4", 0.9 * limit, 1.0, dir.path() / "a").ok);
  CHECK(smallest(dir.path() / "a", "hoist1.tension[N]") > 7e5);
  scene->record.interval = 1.15 * limit;
  const Outcome past = runCase(*scene, "rk4", 1.15 * limit, 1.0, dir.path() / "b");
  if (past.ok) CHECK(smallest(dir.path() / "b", "hoist1.tension[N]") == 0.0);
  else CHECK_THAT(past.failure, Catch::Contains("node") && Catch::Contains("suggestion"));
  scene->record.interval = 0.05;
  const Outcome blown = runCase(*scene, "rk4", 2.0 * limit, 1.0, dir.path() / "c");
  CHECK_FALSE(blown.ok);
  CHECK_THAT(blown.failure, Catch::Contains("node"));
}

TEST_CASE("3500 t block hoisted by its winch: HHT at 0.05 s (25 times RK4's limit) follows the block, at order 2") {
  auto scene = scene::loadSceneOrThrow(example("block_3500t"));
  models::Diagnostics d;
  studies::WpSpec spec = studies::parseWpSpec(*scene, d);
  REQUIRE_FALSE(d.hasErrors());
  spec.until = 1.0;  // the winch starts at 0.2 s
  spec.repeats = 1;
  spec.reference = {"rk4", "rk4", 0.0002, 0.0, {}};
  spec.check = {"cvode_adams", "cvode_adams", 0.0, 1e-11, YAML::Load("{atol: 1.0e-12}")};
  spec.runs = {{"hht", "hht", 0.05, 0.0, YAML::Load("{alpha: -0.1}")},
               {"hht", "hht", 0.025, 0.0, YAML::Load("{alpha: -0.1}")},
               {"hht", "hht", 0.0125, 0.0, YAML::Load("{alpha: -0.1}")},
               {"generalized_alpha", "generalized_alpha", 0.05, 0.0, YAML::Load("{rho_inf: 0.8}")},
               {"generalized_alpha", "generalized_alpha", 0.025, 0.0, YAML::Load("{rho_inf: 0.8}")},
               {"generalized_alpha", "generalized_alpha", 0.0125, 0.0, YAML::Load("{rho_inf: 0.8}")}};
  const auto r = studies::workPrecision(*scene, spec);
  for (std::size_t i = 0; i < r.rows.size(); i += 3) {
    INFO(r.rows[i].run.label << ": E_rms " << r.rows[i].error.rms << " -> " << r.rows[i + 1].error.rms
                             << " -> " << r.rows[i + 2].error.rms << ", omega dt " << r.rows[i].omegaDt);
    for (int k = 0; k < 3; ++k) REQUIRE(r.rows[i + k].status == "ok");
    CHECK(r.rows[i].omegaDt > 60.0);           // far beyond any explicit method's limit
    CHECK(r.rows[i].error.rms <= 1e-2);        // the block's position, m
    // order 2 in the asymptotic range (0.025 -> 0.0125 s)
    CHECK(std::log2(r.rows[i + 1].error.rms / r.rows[i + 2].error.rms) == Approx(2.0).margin(0.3));
  }
}

TEST_CASE("slack and snap: the tension never pushes, and the peak converges to the energy closed form") {
  auto scene = scene::loadSceneOrThrow(example("slack_snap"));
  // m g (h + x) = EA/(2 L0) x^2 with h = 0.5 m: x, and the peak tension EA x / L0
  const double m = 1e4, g = 9.81, k = 2e8 / 20.0, h = 0.5;
  const double x = (m * g + std::sqrt(m * g * m * g + 2 * k * m * g * h)) / k;
  const double exact = k * x;
  testing::SceneDir dir;
  double previous = HUGE_VAL;
  for (double dt : {4e-3, 2e-3, 1e-3, 5e-4}) {
    const auto out = dir.path() / std::to_string(dt);
    REQUIRE(runCase(*scene, "rk4", dt, 1.0, out).ok);
    const testing::CsvFile csv((out / "timeseries.csv").string());
    const int T = csv.column("rope.tension[N]"), L = csv.column("rope.length[m]");
    REQUIRE(T > 0);
    double peak = 0.0, lowest = HUGE_VAL;
    bool slack = false, tautAgain = false;
    for (const auto& row : csv.rows) {
      peak = std::max(peak, row[T]);
      lowest = std::min(lowest, row[T]);
      if (row[L] > 20.0 && slack) tautAgain = true;
      if (row[L] < 20.0) slack = true;
    }
    CHECK(lowest >= 0.0);  // a slack rope exerts nothing, and never pushes
    CHECK(slack);
    CHECK(tautAgain);
    // the recorded peak (1 ms samples) approaches the exact one as the step shrinks
    const double err = std::abs(peak - exact) / exact;
    INFO("dt " << dt << " peak " << peak << " exact " << exact);
    CHECK(err < previous + 1e-4);
    previous = err;
  }
  CHECK(previous < 5e-3);
}

TEST_CASE("mass ratio 1e6: refused at a careless step with a step that works, which then gives a result") {
  testing::SceneDir dir;
  auto scene = scene::loadSceneOrThrow(example("mass_ratio"));
  const auto e = estimateOf(*scene);
  CHECK(e.omegaMax == Approx(std::sqrt((5e6 + 1e8) / 1.0 + 1e8 / 1e6)).epsilon(1e-3));
  const auto v = mechanics::judgeStep(e, "rk4", 0.01);
  REQUIRE_FALSE(v.stable);
  const Outcome o = runCase(*scene, "rk4", v.suggestedDt, 1.5, dir.path() / "a");
  CHECK(o.ok);
  const testing::CsvFile csv((dir.path() / "a" / "timeseries.csv").string());
  const int z = csv.column("block.z[m]"), bal = csv.column("mechanics.energy_balance[J]");
  REQUIRE(z > 0);
  // the block bounces 1 cm about its static position on the rope and link in series, at the
  // slow frequency of the two-mass system (the shackle follows it)
  const double k1 = 5e6, k2 = 1e8, m1 = 1.0, m2 = 1e6;
  const double a = (k1 + k2) / m1 + k2 / m2, b = k1 * k2 / (m1 * m2);
  const double slow = std::sqrt(0.5 * (a - std::sqrt(a * a - 4 * b)));
  const double zStatic = -20.0 - (m1 + m2) * 9.81 / k1 - 1.0 - m2 * 9.81 / k2;
  double worst = 0.0, rise = 0.0;
  for (const auto& row : csv.rows) {
    worst = std::max(worst, std::abs(row[z] - (zStatic + 0.01 * std::cos(slow * row[0]))));
    rise = std::max(rise, row[bal] - csv.rows[0][bal]);
  }
  CHECK(worst < 1e-4);
  CHECK(rise < 1.0);  // RK4 inside its limit only removes energy (from the shackle's fast mode)
}

TEST_CASE("one hour of simulated time: semi-implicit Euler's energy error stays bounded (no drift)",
          "[long]") {
  auto scene = scene::loadSceneOrThrow(example("block_920t"));
  scene->record.interval = 10.0;
  testing::SceneDir dir;
  REQUIRE(runCase(*scene, "semi_implicit_euler", 0.05, 3600.0, dir.path()).ok);
  const testing::CsvFile csv((dir.path() / "timeseries.csv").string());
  const int bal = csv.column("mechanics.energy_balance[J]");
  REQUIRE(csv.rows.size() == 361);
  // (energy error) => its largest magnitude in the first and in the last ten minutes
  double first = 0, last = 0;
  for (std::size_t i = 0; i < csv.rows.size(); ++i) {
    const double err = std::abs(csv.rows[i][bal] - csv.rows[0][bal]);
    (i <= 60 ? first : last) = std::max(i <= 60 ? first : last, i >= 300 || i <= 60 ? err : 0.0);
  }
  INFO("first 10 min " << first << " J, last 10 min " << last << " J");
  CHECK(last < 3.0 * first);  // a symplectic method oscillates; it does not drift
  CHECK(last < 1e6);          // against ~1.3e5 J of motion and 1.9e8 J of potential energy
}

TEST_CASE("slack and snap: the transitions are located events at the closed-form times") {
  // free fall over h: taut at sqrt(2 h / g); then s(t) = ds + R sin(w t - phi) with ds = m g / k,
  // R = sqrt(ds^2 + (v0 / w)^2), sin phi = ds / R: slack again after (pi + 2 phi) / w; the block
  // rises back to where it started and falls again over 2 v0 / g
  const double m = 1e4, g = 9.81, k = 2e8 / 20.0, h = 0.5, w = std::sqrt(k / m);
  const double v0 = std::sqrt(2 * g * h), ds = m * g / k, R = std::hypot(ds, v0 / w), phi = std::asin(ds / R);
  const double taut1 = std::sqrt(2 * h / g), slack1 = taut1 + (M_PI + 2 * phi) / w;
  const double taut2 = slack1 + 2 * v0 / g, slack2 = taut2 + (M_PI + 2 * phi) / w;
  auto scene = scene::loadSceneOrThrow(example("slack_snap"));
  auto root = scene::assemble(*scene);
  devs::Simulator sim(*root);
  testing::RecordCollector rec(false);
  sim.addListener(rec);
  sim.runUntil(1.5);
  std::vector<std::pair<double, std::string>> events;
  for (const auto& r : rec.ofKind("out"))
    if (r.port == "event") events.emplace_back(r.t, r.value);
  REQUIRE(events.size() == 4);
  const double expected[4] = {taut1, slack1, taut2, slack2};
  const char* what[4] = {"taut", "slack", "taut", "slack"};
  for (int i = 0; i < 4; ++i) {
    INFO(events[i].second << " at " << events[i].first << ", expected " << what[i] << " at " << expected[i]);
    CHECK_THAT(events[i].second, Catch::Contains(std::string("rope ") + what[i]) ||
                                     Catch::Contains(std::string(what[i])));
    CHECK(events[i].first == Approx(expected[i]).margin(1e-5));
  }
}
