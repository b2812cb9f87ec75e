// Resource ceilings at the door (issue 14): a step, a period or a record interval that would
// make a run of more steps or rows than the ceiling is refused at its place, with the count and
// the key that raises the ceiling; `limits:` raises it; an end time from the command line is
// checked the same way.
#include "scene/resource_limits.hpp"

#include <catch2/catch.hpp>

#include "scene/scene_loader.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;

namespace {
// (spring step s, record interval s, until s, extra root lines) => the load of that scene
scene::LoadResult load(const testing::SceneDir& dir, const std::string& dt,
                       const std::string& interval, const std::string& until,
                       const std::string& extra = "") {
  return scene::loadScene(
      dir.write("s.yaml",
                "schema_version: 1\ncomponents:\n  s: {type: spring_mass, params: "
                "{mass: 1, stiffness: 1, x0: 1, dt: " +
                    dt +
                    "}}\n"
                    "record: {interval: " +
                    interval + "}\nuntil: " + until + "\n" + extra));
}
}  // namespace

TEST_CASE("a step or record interval beyond the ceilings is refused at its place") {
  testing::SceneDir dir;
  {  // 1e-300 s steps: the run would never end
    const auto r = load(dir, "1.0e-300", "0.1", "5");
    INFO(r.diagnostics.report());
    REQUIRE(r.diagnostics.errorCount() == 1);
    const auto& d = r.diagnostics.all().front();
    CHECK(d.keyPath == "components.s.params.dt");
    CHECK(d.where.line == 3);
    CHECK_THAT(d.message, Catch::Contains("5e+300 steps") && Catch::Contains("ceiling of 1e+08") &&
                              Catch::Contains("limits: {steps:"));
  }
  {  // 1e-6 s rows over 5 s: 5 million rows (the 2 GB in 10 s)
    const auto r = load(dir, "0.01", "1.0e-6", "5");
    INFO(r.diagnostics.report());
    REQUIRE(r.diagnostics.errorCount() == 1);
    CHECK(r.diagnostics.all().front().keyPath == "record.interval");
    CHECK(r.diagnostics.all().front().where.line == 4);
    CHECK_THAT(r.diagnostics.all().front().message, Catch::Contains("5e+06 recorded rows"));
  }
  // at the ceiling exactly: accepted (1e8 steps, 1e6 rows)
  CHECK(load(dir, "1.0e-7", "1.0e-5", "10").scene);
  // no end time: the run ends when no event is left, nothing to count
  CHECK(load(dir, "1.0e-300", "0.1", ".inf").scene == nullptr);  // .inf is not a number of seconds
}

TEST_CASE("limits raises the ceilings and is itself checked") {
  testing::SceneDir dir;
  CHECK(load(dir, "1.0e-9", "1.0e-6", "5", "limits: {steps: 5.0e9, rows: 5.0e6}\n").scene);
  CHECK_FALSE(load(dir, "1.0e-9", "0.1", "5", "limits: {steps: 4.0e9}\n").scene);
  const auto bad = load(dir, "0.1", "0.1", "5", "limits: {steps: .nan, rows: -1, bytes: 3}\n");
  INFO(bad.diagnostics.report());
  CHECK(bad.diagnostics.errorCount() == 3);
  CHECK_THAT(bad.diagnostics.report(),
             Catch::Contains("limits.steps: expected a number from 1 to 1e15") &&
                 Catch::Contains("limits.rows") && Catch::Contains("unknown key 'bytes'"));
}

TEST_CASE("an end time given on the command line is held to the same ceilings") {
  testing::SceneDir dir;
  const auto r = load(dir, "0.01", "0.1", "5");
  REQUIRE(r.scene);
  models::Diagnostics d;
  scene::checkResourceLimits(*r.scene, 1e300, "--until", d);
  INFO(d.report());
  CHECK(d.errorCount() == 2);  // the step and the record interval
  CHECK_THAT(d.report(), Catch::Contains("over --until 1e+300 s"));
  models::Diagnostics fine;
  scene::checkResourceLimits(*r.scene, 1000.0, "--until", fine);
  CHECK_FALSE(fine.hasErrors());
}
