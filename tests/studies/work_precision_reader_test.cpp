// The `wp:` block: sweeps expanded (dt0 / 2^k, one rtol per decade), and mistakes reported at
// their place before anything runs.
#include "studies/work_precision_reader.hpp"

#include <catch2/catch.hpp>

#include "scene/scene_loader.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;

namespace {
const char* kHead = R"(schema_version: 1
integrator: {method: rk4, dt: 0.01}
mechanics:
  bodies:
    block: {parent: world, joint: {type: prismatic, axis: [0, 0, 1], q0: -20.02}, mass: 1.0e4, inertia: [1, 1, 1]}
  ropes:
    rope: {path: [{body: world, point: [0, 0, 0]}, {body: block, point: [0, 0, 0]}], EA: 2.0e8, L0: 20.0}
until: 2
)";

studies::WpSpec parse(const std::string& wp, models::Diagnostics& d) {
  testing::SceneDir dir;
  auto scene = scene::loadSceneOrThrow(dir.write("s.yaml", std::string(kHead) + wp));
  return studies::parseWpSpec(*scene, d);
}
}  // namespace

TEST_CASE("a wp block expands fixed-step sweeps by halving and adaptive ones by decades") {
  models::Diagnostics d;
  const auto spec = parse(R"(wp:
  channels: [block.z]
  interval: 0.1
  methods:
    - {method: rk4, dt0: 0.1, levels: 3}
    - {method: cvode_bdf, rtol: [1.0e-3, 1.0e-6], max_order: 2, label: bdf2}
  reference: {method: rk4, dt: 0.001}
  check: {method: cvode_bdf, rtol: 1.0e-10}
)", d);
  INFO(d.report());
  REQUIRE_FALSE(d.hasErrors());
  REQUIRE(spec.runs.size() == 7);
  CHECK(spec.runs[0].dt == Approx(0.1));
  CHECK(spec.runs[2].dt == Approx(0.025));
  CHECK(spec.runs[2].param() == "dt=0.025");
  CHECK(spec.runs[3].rtol == Approx(1e-3));
  CHECK(spec.runs[6].rtol == Approx(1e-6));
  CHECK(spec.runs[6].param() == "rtol=1e-06");
  CHECK(spec.runs[3].label == "bdf2");
  CHECK(spec.runs[3].method == "cvode_bdf");
  CHECK(spec.runs[3].extra["max_order"].as<int>() == 2);
  CHECK(spec.until == Approx(2.0));
  CHECK(spec.repeats == 3);
  CHECK(spec.check.rtol == Approx(1e-10));
}

TEST_CASE("wp mistakes are reported with their place") {
  models::Diagnostics d;
  parse(R"(wp:
  channels: [block.z]
  interval: 0.1
  methods:
    - {method: rk4, dt0: 0.03, levels: 2}
  reference: {method: rk4}
  check: {method: rk4, dt: 0.001}
  repeat: 2
)", d);
  const std::string report = d.report();
  INFO(report);
  CHECK_THAT(report, Catch::Contains("wp.interval") && Catch::Contains("not a multiple of the step"));
  CHECK_THAT(report, Catch::Contains("wp.reference") && Catch::Contains("give dt"));
  CHECK_THAT(report, Catch::Contains("repeat") && Catch::Contains("repeats"));
  CHECK_THAT(report, Catch::Contains("s.yaml:"));
  CHECK_THAT(report, Catch::Contains("wp.check") && Catch::Contains("different method"));
  models::Diagnostics none;
  parse("", none);
  CHECK_THAT(none.report(), Catch::Contains("no `wp:` block"));
}

TEST_CASE("wp refuses an unknown method and out-of-range levels and repeats at their place") {
  models::Diagnostics d;
  parse(R"(wp:
  channels: [block.z]
  interval: 0.1
  until: 1
  methods:
    - {method: rk5, dt0: 0.01, levels: 2}
    - {method: rk4, dt0: 0.01, levels: 1.0e9}
    - {method: rk4, dt0: 0.01, levels: 2.5}
  reference: {method: rk4, dt: 0.001}
  check: {method: semi_implicit_euler, dt: 0.0001}
  repeats: 1.0e300
)", d);
  const std::string report = d.report();
  INFO(report);
  CHECK_THAT(report, Catch::Contains("s.yaml:14:") && Catch::Contains("wp.methods[0].method") &&
                         Catch::Contains("unknown integrator method"));
  CHECK_THAT(report, Catch::Contains("s.yaml:15:") && Catch::Contains("wp.methods[1].levels") &&
                         Catch::Contains("from 1 to 20"));
  CHECK_THAT(report, Catch::Contains("s.yaml:16:") && Catch::Contains("wp.methods[2].levels"));
  CHECK_THAT(report, Catch::Contains("wp.repeats") && Catch::Contains("from 1 to 1000"));
}

TEST_CASE("wp runs are held to the step and row ceilings of the scene") {
  models::Diagnostics d;
  parse(R"(wp:
  channels: [block.z]
  interval: 1.0e-7
  until: 1
  methods:
    - {method: rk4, dt0: 1.0e-7, levels: 20}
  reference: {method: rk4, dt: 1.0e-9}
  check: {method: semi_implicit_euler, dt: 1.0e-7}
)", d);
  const std::string report = d.report();
  INFO(report);
  CHECK_THAT(report, Catch::Contains("wp.interval") && Catch::Contains("above the ceiling of 1e+06"));
  CHECK_THAT(report, Catch::Contains("wp.methods[0].levels") && Catch::Contains("above the ceiling of 1e+08"));
  CHECK_THAT(report, Catch::Contains("wp.reference.dt") && Catch::Contains("limits: {steps"));
}

TEST_CASE("wp refuses a list or a map where a channel label or file name belongs at its place") {
  // (found by tests/fuzz/mutate.py: `channels: [{a: 1}]` was an internal error, exit 3)
  models::Diagnostics d;
  parse(R"(wp:
  channels: [{a: 1}, block.z]
  interval: 0.1
  methods:
    - {method: rk4, dt0: 0.01, levels: 2, label: [x]}
  reference: {file: {a: 1}}
  check: {method: rk4, dt: 0.001, label: {b: 2}}
)",
        d);
  const std::string report = d.report();
  INFO(report);
  CHECK_THAT(report,
             Catch::Contains("s.yaml:10:14") && Catch::Contains("wp.channels[0]: expected a name"));
  CHECK_THAT(report, Catch::Contains("s.yaml:13:50") &&
                         Catch::Contains("wp.methods[0].label: expected a name"));
  CHECK_THAT(report, Catch::Contains("s.yaml:14:21") &&
                         Catch::Contains("wp.reference.file: expected a name"));
  CHECK_THAT(report,
             Catch::Contains("s.yaml:15:42") && Catch::Contains("wp.check.label: expected a name"));
}
