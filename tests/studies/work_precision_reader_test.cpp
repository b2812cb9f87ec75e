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
