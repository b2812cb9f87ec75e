// The stiffness guard: the verdict against each method's stability limit, and what a scene gets
// for warn, refuse and off (a warning, an error at the integrator block with a suggestion that
// works, nothing); a step longer than the run and a zero step are refused before the run.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <sstream>

#include "scene/scene_loader.hpp"
#include "scene/stiffness_guard.hpp"
#include "support/scene_files.hpp"

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
