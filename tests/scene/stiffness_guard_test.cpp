// The stiffness guard: the verdict against each method's stability limit, and what a scene gets
// for warn, refuse and off (a warning, an error at the integrator block with a suggestion that
// works, nothing); a step longer than the run and a zero step are refused before the run; a marched
// free surface's panel step (rankine_td) against its emp limit, beside the mechanics step.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "forces/geometry/mesh_io.hpp"
#include "forces/geometry/primitive_meshes.hpp"
#include "scene/mechanical_systems.hpp"

#include "scene/scene_loader.hpp"
#include "scene/stiffness_guard.hpp"
#include "support/scene_files.hpp"
#include "support/test_paths.hpp"

using namespace yardsim;

namespace {
// (example scene, text replacements) => its text with them applied
std::string exampleText(const std::string& name) {
  std::ifstream in(std::string(YARDSIM_SOURCE_DIR) + "/examples/stiff/" + name + ".yaml");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}
std::size_t countOf(const models::Diagnostics& d, models::Diagnostic::Severity s) {
  std::size_t n = 0;
  for (const auto& x : d.all()) n += x.severity == s;
  return n;
}
}  // namespace

TEST_CASE("judgeStep compares omega_max dt with each method's stability limit") {
  mechanics::StiffnessEstimate e;
  e.omegaMax = 119.0;
  e.body = "hook";
  CHECK(mechanics::judgeStep(e, "rk4", 0.0125).stable);
  const auto bad = mechanics::judgeStep(e, "rk4", 0.05);
  CHECK_FALSE(bad.stable);
  CHECK(bad.omegaDt == Approx(5.95));
  CHECK(bad.limit == Approx(2.0 * std::sqrt(2.0)));
  CHECK(bad.suggestedDt <= 2.0 * std::sqrt(2.0) / 119.0);
  CHECK(bad.suggestedDt >= 0.8 * 2.0 * std::sqrt(2.0) / 119.0);
  CHECK_THAT(bad.message(), Catch::Contains("hook") && Catch::Contains("suggestion") && Catch::Contains("hht"));
  CHECK(mechanics::judgeStep(e, "semi_implicit_euler", 0.0160).stable);   // 1.90 < 2
  CHECK_FALSE(mechanics::judgeStep(e, "semi_implicit_euler", 0.0170).stable);  // 2.02
  CHECK_FALSE(mechanics::judgeStep(e, "ab4", 0.004).stable);  // 0.476 > 0.43
  CHECK(mechanics::judgeStep(e, "ab3", 0.006).stable);         // 0.714 < 0.72
  // methods that grow every undamped mode are flagged at any step, with an RK4 step that works
  const auto euler = mechanics::judgeStep(e, "explicit_euler", 1e-6);
  CHECK_FALSE(euler.stable);
  CHECK(euler.suggestedDt * 119.0 < 2.83);
  CHECK_FALSE(mechanics::judgeStep(e, "ab2", 1e-6).stable);
  // implicit and adaptive methods have no limit on the imaginary axis
  CHECK(mechanics::judgeStep(e, "hht", 10.0).stable);
  CHECK(mechanics::judgeStep(e, "cvode_bdf", 10.0).stable);
}

TEST_CASE("the hook scene at dt = 0.05 s: refuse is an error at the integrator block, warn a warning, off nothing") {
  testing::SceneDir dir;
  const std::string base = exampleText("hook_hoist_920t");
  SECTION("refuse") {
    const auto f = dir.write("s.yaml", replaced(base, "dt: 0.0125", "dt: 0.05"));
    const auto r = scene::loadScene(f);
    CHECK_FALSE(r.scene);
    REQUIRE(countOf(r.diagnostics, models::Diagnostic::Severity::Error) == 1);
    const auto& d = r.diagnostics.all()[0];
    CHECK(d.keyPath == "integrator.dt");
    CHECK(d.where.line > 0);
    CHECK_THAT(d.message, Catch::Contains("119") && Catch::Contains("hook") && Catch::Contains("dt <= 0.021"));
  }
  SECTION("warn") {
    const auto f = dir.write("s.yaml", replaced(base, "dt: 0.0125, stiffness_check: refuse", "dt: 0.05, stiffness_check: warn"));
    const auto r = scene::loadScene(f);
    CHECK(r.scene);
    CHECK(countOf(r.diagnostics, models::Diagnostic::Severity::Warning) == 1);
  }
  SECTION("off") {
    const auto f = dir.write("s.yaml", replaced(base, "dt: 0.0125, stiffness_check: refuse", "dt: 0.05, stiffness_check: off"));
    const auto r = scene::loadScene(f);
    CHECK(r.scene);
    CHECK(r.diagnostics.all().empty());
  }
  SECTION("the step the scene uses passes") {
    const auto r = scene::loadScene(dir.write("s.yaml", base));
    CHECK(r.scene);
    CHECK(r.diagnostics.all().empty());
  }
  SECTION("an unknown setting is an error with a suggestion") {
    const auto r = scene::loadScene(dir.write("s.yaml", replaced(base, "stiffness_check: refuse", "stiffness_check: refuze")));
    CHECK_FALSE(r.scene);
    CHECK_THAT(r.diagnostics.report(), Catch::Contains("integrator.stiffness_check") && Catch::Contains("refuse"));
  }
}

TEST_CASE("a step longer than the whole run, and a zero step, are refused before the run") {
  testing::SceneDir dir;
  const std::string base = exampleText("slack_snap");
  const auto longer = scene::loadScene(dir.write("a.yaml", replaced(base, "dt: 0.001", "dt: 10")));
  CHECK_FALSE(longer.scene);
  CHECK_THAT(longer.diagnostics.report(), Catch::Contains("integrator.dt") && Catch::Contains("longer than the whole run"));
  const auto zero = scene::loadScene(dir.write("b.yaml", replaced(base, "dt: 0.001", "dt: 0")));
  CHECK_FALSE(zero.scene);
  CHECK_THAT(zero.diagnostics.report(), Catch::Contains("integrator.dt") && Catch::Contains("positive"));
}

namespace {
// (integrator step, panel_step or "" for the default, stiffness_check) => the box barge 20 x 8 m
// of tests/scene/floating_reader_hydrodynamics_test.cpp, its hull marched by rankine_td on a
// coarse free surface (8 panels around, out to 60 m)
std::string markedBarge(const std::string& dt, const std::string& panelStep,
                        const std::string& check = "warn") {
  return "schema_version: 1\nintegrator: {method: rk4, dt: " + dt + ", stiffness_check: " + check + R"(}
mechanics:
  water: {density: 1025}
  bodies:
    barge:
      parent: world
      joint: {type: free, q0: {xyz: [0, 0, 0.5]}}
      mass: 246000
      inertia: [1.64e6, 8.53e6, 9.51e6]
  hydrostatics:
    hull: {body: barge, mesh: meshes/barge.stl}
  hydrodynamics:
    hd: {body: barge, method: rankine_td, hull: meshes/barge.stl, dt: 0.05,
         settings: {truncation_radius: 60, first_spacing: 1.5, max_spacing: 4, longest_period: 4)" +
         (panelStep.empty() ? std::string() : ", panel_step: " + panelStep) + "}}\n";
}
std::string threeDigits(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", x);
  return b;
}
std::string exact(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}
}  // namespace

TEST_CASE("the guard judges a marched free surface's panel step against its emp limit") {
  testing::SceneDir dir;
  std::filesystem::create_directories(dir.path() / "meshes");
  forces::writeStl(forces::boxMesh(dynamics::Vector3(20, 8, 4), 2, 2, 1), dir.file("meshes/barge.stl"));
  // (the panel step at the mechanics step, far below the limit) => no report; the figures
  const auto fine = scene::loadScene(dir.write("fine.yaml", markedBarge("0.05", "")));
  INFO(fine.diagnostics.report());
  REQUIRE(fine.scene);
  CHECK(fine.diagnostics.all().empty());
  const auto& hydro = fine.scene->systems.at(0)->spec.hydrodynamics.at(0);
  REQUIRE(hydro.marchingStep);
  const forces::hydro::MarchingStep m = hydro.marchingStep();
  INFO("emp limit " << m.limit << " s, lambda_max " << m.lambdaMax << " 1/m");
  CHECK(m.scheme == "emp");
  CHECK(m.step == 0.05);
  // (the limit is g lambda_max dt^2 = 4, g the scene's 9.81) => stability number 4 at the limit
  CHECK(9.81 * m.lambdaMax * m.limit * m.limit == Approx(4.0).epsilon(1e-12));
  CHECK(m.stabilityNumber() == Approx(4.0 * std::pow(0.05 / m.limit, 2)).epsilon(1e-12));
  // (panels of 1.5 m and more: lambda_max h ~ 3, dt <= 1.15 sqrt(h / g) ~ 0.45 s)
  CHECK(m.limit > 0.2);
  CHECK(m.limit < 1.5);
  auto warnings = [](const scene::LoadResult& r) {
    std::vector<const models::Diagnostic*> out;
    for (const auto& d : r.diagnostics.all())
      if (d.keyPath == "mechanics.hydrodynamics.hd") out.push_back(&d);
    return out;
  };
  SECTION("within 10 % of the limit: a warning at the entry with both numbers and the mechanics step") {
    // (dt a quarter of 0.95 of the limit, the panel step four of them) => a whole multiple
    const double dt = std::floor(0.95 * m.limit / 4.0 * 1e4) / 1e4, step = 4.0 * dt;
    const auto r = scene::loadScene(dir.write("near.yaml", markedBarge(exact(dt), exact(step))));
    INFO(r.diagnostics.report());
    REQUIRE(r.scene);
    const auto found = warnings(r);
    REQUIRE(found.size() == 1);
    const models::Diagnostic& d = *found[0];
    CHECK(d.severity == models::Diagnostic::Severity::Warning);
    CHECK(d.where.line == 14);
    CHECK(d.element == "hd");
    CHECK(d.value == Approx(step / m.limit));
    CHECK_THAT(d.message, Catch::Contains("panel step " + threeDigits(step) + " s") &&
                              Catch::Contains("emp limit " + threeDigits(m.limit) + " s") &&
                              Catch::Contains("lambda_max " + threeDigits(m.lambdaMax)) &&
                              Catch::Contains("rk4 at dt = " + threeDigits(dt)) &&
                              Catch::Contains("omega_max dt =") && Catch::Contains("2.83"));
    const auto refused = scene::loadScene(dir.write("near_refuse.yaml", markedBarge(exact(dt), exact(step), "refuse")));
    CHECK_FALSE(refused.scene);
    CHECK_THAT(refused.diagnostics.report(), Catch::Contains("emp limit") && Catch::Contains("stiffness_check: refuse"));
    const auto off = scene::loadScene(dir.write("near_off.yaml", markedBarge(exact(dt), exact(step), "off")));
    CHECK(off.scene);
    CHECK(off.diagnostics.all().empty());
  }
  SECTION("at 0.85 of the limit nothing is reported") {
    const double dt = std::floor(0.85 * m.limit / 4.0 * 1e4) / 1e4;
    const auto r = scene::loadScene(dir.write("below.yaml", markedBarge(exact(dt), exact(4.0 * dt))));
    INFO(r.diagnostics.report());
    CHECK(r.scene);
    CHECK(r.diagnostics.all().empty());
  }
  SECTION("a panel step that is not a whole multiple of the mechanics step") {
    const auto r = scene::loadScene(dir.write("odd.yaml", markedBarge("0.05", "0.07")));
    INFO(r.diagnostics.report());
    const auto found = warnings(r);
    REQUIRE(found.size() == 1);
    CHECK_THAT(found[0]->message, Catch::Contains("panel step 0.07 s is not a whole multiple of the mechanics step 0.05 s") &&
                                      Catch::Contains("panel_step 0.05 s"));
  }
  SECTION("above the limit: refused at the entry with the numbers") {
    const double step = 1.05 * m.limit;
    const auto r = scene::loadScene(dir.write("above.yaml", markedBarge(exact(step), exact(step))));
    CHECK_FALSE(r.scene);
    const auto found = warnings(r);
    REQUIRE_FALSE(found.empty());
    CHECK(found[0]->severity == models::Diagnostic::Severity::Error);
    char limit[32];
    std::snprintf(limit, sizeof limit, "%.4g", m.limit);
    CHECK_THAT(found[0]->message, Catch::Contains("above the emp limit " + std::string(limit) + " s") &&
                                      Catch::Contains("lambda_max"));
  }
}
