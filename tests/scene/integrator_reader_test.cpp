// The scene's `integrator:` block: every key read into the spec, mistakes reported at their
// file:line:column with "did you mean", keys the method ignores warned about, and every method
// running a scene's mechanics to the same motion.
#include "scene/integrator_reader.hpp"

#include <catch2/catch.hpp>
#include <cmath>

#include "devs/simulator.hpp"
#include "scene/assembler.hpp"
#include "models/channels.hpp"
#include "models/multibody/multibody_model.hpp"
#include "scene/scene_loader.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;

namespace {

// a pendulum released at 0.5 rad, with the given integrator line
std::string pendulum(const std::string& integrator) {
  return "schema_version: 1\n" + integrator + R"(
until: 2
mechanics:
  bodies:
    bob: {parent: world, joint: {type: revolute, axis: [0, 1, 0], q0: 0.5}, mass: 1, com: [0, 0, -1], inertia: [0.01, 0.01, 0.01]}
)";
}

scene::LoadResult load(const testing::SceneDir& dir, const std::string& integrator) {
  return scene::loadScene(dir.write("s.yaml", pendulum(integrator)));
}

}  // namespace

TEST_CASE("the integrator block is read into the spec") {
  testing::SceneDir dir;
  auto r = load(dir, "integrator: {method: hht, dt: 0.02, alpha: -0.2}");
  INFO(r.diagnostics.report());
  REQUIRE(r.scene);
  CHECK(r.scene->integrator == "hht");
  CHECK(r.scene->dt == 0.02);
  CHECK(r.scene->integratorSpec.method == "hht");
  CHECK(r.scene->integratorSpec.dt == 0.02);
  CHECK(r.scene->integratorSpec.alpha == -0.2);
  r = load(dir, "integrator: {method: cvode_bdf, dt: 0.1, rtol: 1e-7, atol: 1e-9, max_order: 2, max_step: 0.01, "
                "loops: baumgarte, baumgarte_alpha: 5, baumgarte_beta: 6}");
  INFO(r.diagnostics.report());
  REQUIRE(r.scene);
  const auto& s = r.scene->integratorSpec;
  CHECK(s.rtol == 1e-7);
  CHECK(s.atol == 1e-9);
  CHECK(s.maxOrder == 2);
  CHECK(s.maxStep == 0.01);
  CHECK(s.loops == dynamics::LoopStabilization::Baumgarte);
  CHECK(s.baumgarteAlpha == 5);
  CHECK(s.baumgarteBeta == 6);
  CHECK(r.diagnostics.all().empty());
}

TEST_CASE("integrator mistakes are reported at file:line:column with did-you-mean") {
  testing::SceneDir dir;
  // line 2 of s.yaml; the method value starts at column 22
  auto r = load(dir, "integrator: {method: hhtt, dt: 0.02}");
  REQUIRE_FALSE(r.scene);
  CHECK_THAT(r.diagnostics.report(), Catch::Contains("s.yaml:2:22: error: integrator.method: unknown integration "
                                                     "method 'hhtt'") &&
                                         Catch::Contains("did you mean 'hht'?") && Catch::Contains("arkode_imex"));
  r = load(dir, "integrator: {method: hht, dt: 0.02, alpah: -0.1}");
  REQUIRE_FALSE(r.scene);
  CHECK_THAT(r.diagnostics.report(), Catch::Contains("s.yaml:2:37: error: integrator.alpah: unknown key 'alpah'") &&
                                         Catch::Contains("did you mean 'alpha'?"));
  r = load(dir, "integrator: {method: hht, dt: 0.02, alpha: -0.5}");
  REQUIRE_FALSE(r.scene);
  CHECK_THAT(r.diagnostics.report(),
             Catch::Contains("s.yaml:2:44: error: integrator.alpha: HHT needs alpha in [-1/3, 0], got -0.5"));
  r = load(dir, "integrator: {method: generalized_alpha, dt: 0.02, rho_inf: high, loops: projektion}");
  REQUIRE_FALSE(r.scene);
  CHECK_THAT(r.diagnostics.report(), Catch::Contains("integrator.rho_inf: expected a number, got 'high'") &&
                                         Catch::Contains("integrator.loops: expected projection, baumgarte or none") &&
                                         Catch::Contains("did you mean 'projection'?"));
  // an integer beyond an int is a located error, not an internal fault (was exit 3: yaml-cpp threw)
  r = load(
      dir,
      "integrator: {method: cvode_bdf, dt: 0.02, max_order: 3000000000, max_newton: -99999999999}");
  REQUIRE_FALSE(r.scene);
  CHECK_THAT(
      r.diagnostics.report(),
      Catch::Contains(
          "s.yaml:2:54: error: integrator.max_order: expected an integer of magnitude at most "
          "2147483647, got '3000000000'") &&
          Catch::Contains("error: integrator.max_newton: expected an integer of magnitude"));
  // a key the method does not use: a warning, the scene still loads
  r = load(dir, "integrator: {method: rk4, dt: 0.02, alpha: -0.1}");
  REQUIRE(r.scene);
  CHECK_THAT(r.diagnostics.report(),
             Catch::Contains("warning: integrator.alpha: 'alpha' is a parameter of hht; method rk4 ignores it"));
}

TEST_CASE("every method steps a scene's mechanics and follows the same pendulum") {
  testing::SceneDir dir;
  // (method) => bob angle at t = 2 s, and the integrator the scene's system got
  auto run = [&](const std::string& line, std::string& name) {
    const auto r = load(dir, line);
    INFO(r.diagnostics.report());
    REQUIRE(r.scene);
    auto root = scene::assemble(*r.scene);
    const auto* mb = dynamic_cast<const models::MultibodyModel*>(root->findComponent("mechanics"));
    REQUIRE(mb != nullptr);
    name = std::string(mb->integrator().name());
    devs::Simulator sim(*root);
    sim.runUntil(2.0);
    CHECK(mb->integratorStats().steps > 0);
    for (const auto& c : models::collectChannels(*root))
      if (c.name == "bob_joint.q" || c.name == "bob.q") return c.read();
    FAIL("no joint angle channel");
    return 0.0;
  };
  std::string name;
  const double reference = run("integrator: {method: rk4, dt: 0.001}", name);
  for (const auto& m : dynamics::integratorMethodNames()) {
    const bool adaptive = dynamics::findMethod(m)->adaptive;
    const double dt = adaptive ? 0.05 : (m == "explicit_euler" ? 1e-4 : 0.002);
    const double tol = m == "explicit_euler" || m == "semi_implicit_euler" ? 2e-2 : 2e-3;
    const double q = run("integrator: {method: " + m + ", dt: " + std::to_string(dt) + "}", name);
    INFO(m << ": " << q << " against " << reference);
    CHECK(name == m);
    CHECK(q == Approx(reference).margin(tol));
  }
}

TEST_CASE("an infinite or negative dt is one error at its value") {
  testing::SceneDir dir;
  for (const char* dt : {".inf", "-0.01", ".nan"}) {
    const auto r = load(dir, std::string("integrator: {method: rk4, dt: ") + dt + "}");
    INFO(r.diagnostics.report());
    REQUIRE_FALSE(r.scene);
    REQUIRE(r.diagnostics.errorCount() == 1);  // was three for .inf: reader, spec check, run settings
    CHECK(r.diagnostics.all().front().keyPath == "integrator.dt");
    CHECK_THAT(r.diagnostics.all().front().message, Catch::Contains("expected a positive number of seconds"));
  }
}
