// The worst value of a watch crossing is the watched quantity's extreme beyond its threshold, with
// its time, not the threshold the event is located at. A pendulum let go at rest from -theta0
// swings to +theta0 (energy conservation) at half its period and back to -theta0 at the full
// period; an upper watch at +theta0 / 2 and a lower one at -theta0 / 2 must report +theta0 at
// T / 2 and -theta0 at T.
#include "run/watch_extremes.hpp"

#include <yaml-cpp/yaml.h>
#include <catch2/catch.hpp>
#include <cmath>

#include "run/runner.hpp"
#include "scene/assembler.hpp"
#include "scene/scene_loader.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;

namespace {
// A 1 kg bob 1 m below a hinge about y (inertia about its centre 1e-3 kg m^2), let go at rest
// from q = -0.1 rad.
const char* kPendulum = R"(schema_version: 1
integrator: {method: rk4, dt: 0.001}
until: 2.5
mechanics:
  bodies:
    bob:
      parent: world
      joint: {name: hinge, type: revolute, axis: [0, 1, 0], q0: -0.1}
      mass: 1.0
      com: [0, 0, -1.0]
      inertia: [1.0e-3, 1.0e-3, 1.0e-3]
  watch:
    swing_out: {channel: hinge.q, above: 0.05}
    swing_back: {channel: hinge.q, below: -0.05}
)";
}  // namespace

TEST_CASE(
    "a crossed alarm's worst value is the swing's amplitude beyond the threshold with its time") {
  testing::SceneDir dir;
  auto scene = scene::loadSceneOrThrow(dir.write("s.yaml", kPendulum));
  auto root = scene::assemble(*scene);
  run::RunOptions opt{dir.path() / "out", scene->until, {}, {}, 0.1, 2000};
  const auto r = run::runScene(*scene, *root, opt);
  // (compound pendulum) => T = 2 pi sqrt(I_O / (m g l)) (1 + theta0^2 / 16 + ...)
  const double theta0 = 0.1, g = 9.81, m = 1.0, l = 1.0, iO = 1.0e-3 + m * l * l;
  const double period = 2 * M_PI * std::sqrt(iO / (m * g * l)) * (1 + theta0 * theta0 / 16);
  auto find = [&](const std::string& element) -> const run::Alarm* {
    for (const auto& a : r.alarms)
      if (a.element == element && a.kind == "crossed") return &a;
    return nullptr;
  };
  const run::Alarm* out = find("swing_out");
  const run::Alarm* back = find("swing_back");
  REQUIRE(out);
  REQUIRE(back);
  // (first crossings) => where the swing passes the thresholds: -theta0 cos(w t) = +-theta0 / 2
  // at w t = 2 pi / 3 going out and 5 pi / 3 coming back (it starts beyond the lower one)
  CHECK(out->first == Approx(period / 3).epsilon(2e-3));
  CHECK(back->first == Approx(5 * period / 6).epsilon(2e-3));
  // (worst) => the amplitude, sampled at the steps (dt = 1 ms: within 1e-6 rad of the peak),
  // at the peak's time to within a step
  CHECK(out->worst == Approx(theta0).epsilon(1e-5));
  CHECK(std::abs(out->worstAt - period / 2) < 2e-3);
  CHECK(back->worst == Approx(-theta0).epsilon(1e-5));
  CHECK(std::abs(back->worstAt - period) < 2e-3);
  CHECK(out->count == 1);
  CHECK(back->count == 1);
  // (run.json) => the same worst values and times
  const YAML::Node json = YAML::LoadFile((dir.path() / "out/run.json").string());
  bool seen = false;
  for (const auto& a : json["alarms"])
    if (a["element"].as<std::string>() == "swing_out") {
      seen = true;
      CHECK(a["worst"].as<double>() == out->worst);
      CHECK(a["worst_at"].as<double>() == out->worstAt);
      CHECK(a["unit"].as<std::string>() == "rad");
    }
  CHECK(seen);
}

TEST_CASE("without a crossing the worst value is left alone") {
  // (a watch the swing never reaches) => no alarm at all, whatever the extremes read
  testing::SceneDir dir;
  std::string text = kPendulum;
  text.replace(text.find("above: 0.05"), 11, "above: 0.15");
  auto scene = scene::loadSceneOrThrow(dir.write("s.yaml", text));
  auto root = scene::assemble(*scene);
  const auto r = run::runScene(*scene, *root, {dir.path() / "out", 1.5, {}, {}, 0.1, 2000});
  for (const auto& a : r.alarms) CHECK(a.element != "swing_out");
}
