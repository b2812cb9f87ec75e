// The `wind` block with `gusts` from YAML: the gust series is the library's for the same keys,
// the model's `wind_speed` channel shows it at the reference height (and a steady wind has no
// such channel), and bad gusts are refused at their line with the key path.
#include "scene/wind_reader.hpp"

#include <catch2/catch.hpp>

#include "devs/simulator.hpp"
#include "models/channels.hpp"
#include "scene/assembler.hpp"
#include "scene/mechanical_systems.hpp"
#include "scene/scene_loader.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;
using Catch::Matchers::Contains;

namespace {

// (the wind's block, on line 5) => a 500 t box on a free joint under a wind load, no gravity
std::string sceneYaml(const std::string& wind) {
  return R"(schema_version: 1
integrator: {method: rk4, dt: 0.05}
mechanics:
  gravity: [0, 0, 0]
)" + wind +
         R"(  bodies:
    box:
      parent: world
      joint: {type: free, q0: {xyz: [0, 0, 20]}}
      mass: 5.0e5
      inertia: [1.0e7, 1.0e7, 1.0e7]
  wind_loads:
    wind: {body: box, point: [0, 0, 0], frontal_area: 100, lateral_area: 300, length: 30}
)";
}

// (channels, name ending) => the one channel whose name ends so
const models::Channel* ending(const std::vector<models::Channel>& all, const std::string& tail) {
  const models::Channel* found = nullptr;
  for (const auto& c : all)
    if (c.name.size() >= tail.size() &&
        c.name.compare(c.name.size() - tail.size(), tail.size(), tail) == 0) {
      if (found) FAIL("two channels end with " << tail);
      found = &c;
    }
  return found;
}

const models::Diagnostic* find(const scene::LoadResult& r, const std::string& keyPath) {
  for (const auto& d : r.diagnostics.all())
    if (d.keyPath == keyPath) return &d;
  return nullptr;
}

}  // namespace

TEST_CASE("gusts from YAML: the library's series, shown by the wind_speed channel") {
  testing::SceneDir dir;
  const auto r = scene::loadScene(dir.write(
      "s.yaml",
      sceneYaml(
          "  wind: {speed: 15, direction_deg: -90, profile: npd,\n"
          "         gusts: {spectrum: npd, seed: 11, components: 120, f_min: 0.0005, f_max: 0.5,\n"
          "                 height: 20, start: 1, ramp: 2}}\n")));
  INFO(r.diagnostics.report());
  REQUIRE(r.scene);
  const auto& wind = r.scene->systems.at(0)->spec.wind;
  REQUIRE(wind);
  REQUIRE(wind->gusts);
  CHECK(wind->averagingTime == 3600.0);
  // (the same keys through the library) => the same series, bit for bit
  forces::GustProperties g;
  g.seed = 11, g.components = 120, g.fMin = 0.0005, g.fMax = 0.5, g.height = 20, g.start = 1,
  g.ramp = 2;
  const forces::WindGusts expected(g, 15.0);
  const forces::WindField field(*wind);
  for (double t : {0.5, 2.0, 7.3, 100.0}) CHECK(field.gust(t) == expected.speed(t));
  // (the channel) => the 1-hour mean at 10 m plus the gust, ramped in from t = 1 s over 2 s
  auto root = scene::assemble(*r.scene);
  const auto ch = models::collectChannels(*root);
  const models::Channel* speed = ending(ch, "wind_speed");
  REQUIRE(speed);
  CHECK(speed->unit == "m/s");
  CHECK(speed->read() == 15.0);  // before the start: the mean
  devs::Simulator sim(*root);
  sim.runUntil(10.0);
  CHECK(speed->read() == Approx(15.0 + expected.speed(10.0)).epsilon(1e-12));
  CHECK(std::abs(expected.speed(10.0)) > 1e-3);
  // (a steady wind) => no wind_speed channel
  const auto steady =
      scene::loadScene(dir.write("t.yaml", sceneYaml("  wind: {speed: 15, profile: npd}\n")));
  REQUIRE(steady.scene);
  CHECK_FALSE(steady.scene->systems.at(0)->spec.wind->gusts);
  auto root2 = scene::assemble(*steady.scene);
  CHECK(ending(models::collectChannels(*root2), "wind_speed") == nullptr);
}

TEST_CASE("bad gusts are refused at their line with the key path") {
  testing::SceneDir dir;
  auto load = [&](const std::string& wind) {
    return scene::loadScene(dir.write("s.yaml", sceneYaml(wind)));
  };
  SECTION("an unknown spectrum, a misspelt key") {
    const auto r =
        load("  wind:\n    speed: 15\n    profile: npd\n    gusts: {spectrum: npdd, seeds: 3}\n");
    INFO(r.diagnostics.report());
    const auto* s = find(r, "mechanics.wind.gusts.seeds");
    REQUIRE(s);
    CHECK(s->where.line == 8);
    CHECK_THAT(s->message + s->hint, Contains("did you mean 'seed'?"));
    const auto again =
        load("  wind:\n    speed: 15\n    profile: npd\n    gusts: {spectrum: npdd}\n");
    const auto* k = find(again, "mechanics.wind.gusts.spectrum");
    REQUIRE(k);
    CHECK(k->where.line == 8);
    CHECK_THAT(k->message + k->hint, Contains("did you mean 'npd'?"));
  }
  SECTION("no components, a NaN band edge, f_max below f_min, a negative ramp, no spectrum") {
    const auto r = load(
        "  wind:\n    speed: 15\n    profile: npd\n    gusts:\n      spectrum: npd\n      "
        "components: 0\n"
        "      f_min: .nan\n      ramp: -3\n");
    INFO(r.diagnostics.report());
    const auto* n = find(r, "mechanics.wind.gusts.components");
    REQUIRE(n);
    CHECK(n->where.line == 10);
    CHECK_THAT(n->message, Contains("whole number in [1, 100000]"));
    const auto* f = find(r, "mechanics.wind.gusts.f_min");
    REQUIRE(f);
    CHECK(f->where.line == 11);
    CHECK_THAT(f->message, Contains("expected a number"));
    const auto* ramp = find(r, "mechanics.wind.gusts.ramp");
    REQUIRE(ramp);
    CHECK(ramp->where.line == 12);
    const auto band = load(
        "  wind: {speed: 15, profile: npd, gusts: {spectrum: npd, f_min: 0.1, f_max: 0.05}}\n");
    const auto* hi = find(band, "mechanics.wind.gusts.f_max");
    REQUIRE(hi);
    CHECK(hi->where.line == 5);
    CHECK_THAT(hi->message, Contains("above f_min"));
    const auto none = load("  wind: {speed: 15, profile: npd, gusts: {seed: 2}}\n");
    const auto* sp = find(none, "mechanics.wind.gusts");
    REQUIRE(sp);
    CHECK_THAT(sp->message, Contains("missing required key 'spectrum'"));
  }
  SECTION("gusts on a power law, or with a 1-minute mean") {
    const auto r = load("  wind:\n    speed: 15\n    gusts: {spectrum: npd}\n");
    INFO(r.diagnostics.report());
    const auto* p = find(r, "mechanics.wind.gusts");
    REQUIRE(p);
    CHECK(p->where.line == 7);
    CHECK_THAT(p->message, Contains("profile: npd"));
    const auto a = load(
        "  wind:\n    speed: 15\n    profile: npd\n    averaging_time: 60\n    gusts: {spectrum: "
        "npd}\n");
    INFO(a.diagnostics.report());
    const auto* t = find(a, "mechanics.wind.averaging_time");
    REQUIRE(t);
    CHECK(t->where.line == 8);
    CHECK_THAT(t->message, Contains("1-hour mean"));
  }
}
