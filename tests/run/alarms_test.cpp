// Safety events made visible: a block caught by a rope whose breaking load is 0.9 m g raises one
// over_mbl alarm as the rope takes the load after a 1 mm fall, a watch on the block's depth raises
// a `crossed` alarm, the rope going taut is a notice; run.json lists them, and per rope its peak,
// when, the static tension (m g in the end: here the report's static level), peak/static and
// peak/MBL.
#include "run/alarms.hpp"

#include <yaml-cpp/yaml.h>
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <sstream>

#include "run/runner.hpp"
#include "scene/assembler.hpp"
#include "scene/scene_loader.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;

namespace {
const char* kScene = R"(schema_version: 1
integrator: {method: rk4, dt: 0.001}
until: 2
record: {interval: 0.01}
report: {static: {hoist.tension: 9810}}
mechanics:
  bodies:
    block:
      parent: world
      joint: {name: lift, type: prismatic, axis: [0, 0, 1], q0: -9.999}
      mass: 1000.0
      inertia: [100, 100, 100]
  ropes:
    hoist:
      path: [{body: world, point: [0, 0, 0]}, {body: block, point: [0, 0, 0]}]
      EA: 1.0e8
      L0: 10.0
      damping: 2.0e5
      mbl: 8829.0
  watch:
    deep: {channel: lift.q, below: -10.00095}
)";
}  // namespace

TEST_CASE("a rope over its MBL and a watch crossing are alarms, in run.json with the rope's peak") {
  testing::SceneDir dir;
  auto scene = scene::loadSceneOrThrow(dir.write("s.yaml", kScene));
  auto root = scene::assemble(*scene);
  std::vector<run::Alarm> firsts;
  run::RunOptions opt{dir.path() / "out", scene->until, {}, {}, 0.1, 2000};
  opt.onAlarm = [&](const run::Alarm& a) { firsts.push_back(a); };
  const auto r = run::runScene(*scene, *root, opt);
  // (events) => over_mbl once, crossed once, taut a notice; each reported once when it first
  // happens
  auto find = [&](const std::string& kind) -> const run::Alarm* {
    for (const auto& a : r.alarms)
      if (a.kind == kind) return &a;
    return nullptr;
  };
  const run::Alarm* mbl = find("over_mbl");
  REQUIRE(mbl);
  CHECK(mbl->element == "hoist");
  CHECK(mbl->severity == "alarm");
  CHECK(mbl->count == 1);
  // (free fall of h = 1 mm, then the damper at the catch) => the rope goes taut and over its
  // MBL at the same instant t = sqrt(2 h / g), with the tension c sqrt(2 g h) (the stretch is 0;
  // within 2 %: the located state comes from a step whose last stage already feels the rope)
  const double g = 9.81, h = 0.001;
  CHECK(mbl->first == Approx(std::sqrt(2 * h / g)).epsilon(1e-6));
  CHECK(mbl->worst == Approx(2.0e5 * std::sqrt(2 * g * h)).epsilon(0.02));
  const run::Alarm* deep = find("crossed");
  REQUIRE(deep);
  CHECK(deep->element == "deep");
  CHECK(deep->severity == "alarm");
  const run::Alarm* taut = find("taut");
  REQUIRE(taut);
  CHECK(taut->severity == "notice");
  CHECK(taut->first == mbl->first);  // reached together: neither is lost
  CHECK(firsts.size() == r.alarms.size());
  // (run.json) => the same list, and the rope's loads
  const YAML::Node json = YAML::LoadFile((dir.path() / "out/run.json").string());
  REQUIRE(json["alarms"].size() == r.alarms.size());
  CHECK(json["alarms"][0]["kind"].as<std::string>() == r.alarms[0].kind);
  // (each alarm's worst value) => with its SI unit: the tension in N, the watched lift.q in m
  for (const auto& a : json["alarms"]) {
    const auto kind = a["kind"].as<std::string>();
    CHECK(a["unit"].as<std::string>() == (kind == "over_mbl" ? "N" : "m"));  // taut: a length
  }
  REQUIRE(json["ropes"].size() == 1);
  const YAML::Node rope = json["ropes"][0];
  CHECK(rope["name"].as<std::string>() == "hoist");
  const double peak = rope["peak"].as<double>();
  CHECK(peak > 8829.0);       // it did pass the MBL
  CHECK(peak == mbl->worst);  // at the catch: the damper, then a critically damped decay
  CHECK(rope["peak_time"].as<double>() == mbl->first);
  CHECK(rope["static"].as<double>() == 9810.0);  // the report's static level
  CHECK(rope["peak_over_static"].as<double>() == Approx(peak / 9810.0));
  CHECK(rope["mbl_utilisation"].as<double>() == Approx(peak / 8829.0));
}

TEST_CASE("a run without safety events lists none") {
  run::AlarmMonitor m;
  CHECK(m.alarms().empty());
  CHECK(m.alarmCount() == 0);
}

TEST_CASE("over_mbl's worst value is the rope's peak tension not the MBL it crossed") {
  // (a block let go at zero stretch on an undamped rope) => the tension crosses the MBL (0.9 m g)
  // on its way up and peaks at 2 m g (energy: m g x = k x^2 / 2); the event is located at the
  // crossing, where the tension is the MBL
  testing::SceneDir dir;
  std::string text = kScene;
  text.replace(text.find("q0: -9.999"), 10, "q0: -10.0");
  text.replace(text.find("damping: 2.0e5"), 14, "damping: 0.0");
  text.replace(text.find("until: 2"), 8,
               "until: 0.05");  // one swing: the peak at pi / omega = 0.031 s
  auto scene = scene::loadSceneOrThrow(dir.write("s.yaml", text));
  auto root = scene::assemble(*scene);
  std::vector<run::Alarm> firsts;
  run::RunOptions opt{dir.path() / "out", scene->until, {}, {}, 0.1, 2000};
  opt.onAlarm = [&](const run::Alarm& a) { firsts.push_back(a); };
  const auto r = run::runScene(*scene, *root, opt);
  const double m = 1000.0, g = 9.81;
  REQUIRE(!firsts.empty());
  CHECK(firsts[0].kind == "over_mbl");
  CHECK(firsts[0].worst == Approx(8829.0).epsilon(1e-6));  // at the crossing, as located
  const run::Alarm& mbl = r.alarms[0];
  REQUIRE(mbl.kind == "over_mbl");
  CHECK(mbl.count == 1);
  CHECK(mbl.worst == Approx(2 * m * g).epsilon(2e-3));  // the peak, after the crossing
  const YAML::Node json = YAML::LoadFile((dir.path() / "out/run.json").string());
  CHECK(json["alarms"][0]["worst"].as<double>() == mbl.worst);
  CHECK(json["ropes"][0]["peak"].as<double>() == mbl.worst);
}

TEST_CASE("a warning of the scene is one warning alarm per text and counts its repeats") {
  // (the stiffness guard's warning, twice; another one) => two warnings, the first counted twice,
  // each reported once at its first occurrence, with its element, value and located text
  std::vector<run::Alarm> firsts;
  run::AlarmMonitor m([&](const run::Alarm& a) { firsts.push_back(a); });
  models::Diagnostics d;
  d.warning({"s.yaml", 2, 13}, "integrator.dt", "mechanical system 'm': too long a step", {},
            "hook", 3.5);
  d.warning({"s.yaml", 9, 3}, "components.x", "input port 'in' of 'x' is not connected");
  m.warn(d.all()[0], 0.0);
  m.warn(d.all()[0], 0.0);
  m.warn(d.all()[1], 0.0);
  REQUIRE(m.alarms().size() == 2);
  CHECK(firsts.size() == 2);
  CHECK(m.warningCount() == 2);
  CHECK(m.alarmCount() == 0);  // warnings are not safety alarms
  const run::Alarm& guard = m.alarms()[0];
  CHECK(guard.kind == "warning");
  CHECK(guard.severity == "warning");
  CHECK(guard.element == "hook");
  CHECK(guard.count == 2);
  CHECK(guard.worst == 3.5);
  CHECK(guard.message == "s.yaml:2:13: integrator.dt: mechanical system 'm': too long a step");
  const run::Alarm& port = m.alarms()[1];
  CHECK(port.element == "components.x");  // no element: its key path
  CHECK(std::isnan(port.worst));
  // (a restart that finds them in its checkpoint) => not counted again
  m.warn(d.all()[0], 5.0, false);
  CHECK(m.alarms()[0].count == 2);
  CHECK(m.alarms()[0].first == 0.0);
}

TEST_CASE("worsen moves a known alarm's worst value in the direction that is worse") {
  run::AlarmMonitor m;
  m.raise("mb", "low", "crossed", true, 1.0, -2.0);
  m.worsen("mb", "low", "crossed", false, 1.5, -2.5);    // a lower limit: smaller is worse
  m.worsen("mb", "low", "crossed", false, 2.0, -2.2);    // not worse
  m.worsen("mb", "other", "crossed", false, 2.0, -9.0);  // unknown: left alone
  REQUIRE(m.alarms().size() == 1);
  CHECK(m.alarms()[0].worst == -2.5);
  CHECK(m.alarms()[0].worstAt == 1.5);
  CHECK(m.alarms()[0].count == 1);
  m.raise("mb", "high", "crossed", true, 1.0, 0.4);  // an upper limit on a positive quantity
  m.worsen("mb", "high", "crossed", true, 1.2, 0.7);
  m.worsen("mb", "high", "crossed", true, 1.3, 0.5);
  CHECK(m.alarms()[1].worst == 0.7);
  CHECK(m.alarms()[1].worstAt == 1.2);
}
