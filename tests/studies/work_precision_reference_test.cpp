// A published reference for `yardsim wp`: a body in free fall against the closed form z0 - g t^2 / 2
// written to a CSV file. Explicit Euler's error is then known exactly (g t h / 2), RK4's is
// round-off, and bad files are refused naming the file.
#include "studies/work_precision_reference.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <sstream>

#include "scene/scene_loader.hpp"
#include "studies/work_precision.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;

namespace {
const char* kFall = R"(schema_version: 1
name: fall
integrator: {method: rk4, dt: 0.01}
mechanics:
  bodies:
    block: {parent: world, joint: {type: prismatic, axis: [0, 0, 1], q0: 100}, mass: 10, inertia: [1, 1, 1]}
until: 1
wp:
  channels: [block.z]
  interval: 0.1
  methods:
    - {method: explicit_euler, dt0: 0.01, levels: 2}
    - {method: rk4, dt0: 0.05, levels: 1}
  reference: {file: fall_reference.csv}
  repeats: 1
)";

// (times) => the closed form, as a yardsim timeseries.csv would hold it
std::string closedForm(double dt, double until) {
  std::ostringstream s;
  s.precision(17);
  s << "# the exact free fall from 100 m\ntime[s],block.x[m],block.z[m]\n";
  for (int k = 0; k * dt <= until + 1e-12; ++k) {
    const double t = k * dt;
    s << t << ",0," << 100.0 - 0.5 * 9.81 * t * t << "\n";
  }
  return s.str();
}
}  // namespace

TEST_CASE("wp against a published reference file: explicit Euler's error is g t h / 2, RK4's none") {
  testing::SceneDir dir;
  dir.write("fall_reference.csv", closedForm(0.1, 1.0));
  auto scene = scene::loadSceneOrThrow(dir.write("fall.yaml", kFall));
  models::Diagnostics d;
  const studies::WpSpec spec = studies::parseWpSpec(*scene, d);
  INFO(d.report());
  REQUIRE_FALSE(d.hasErrors());
  CHECK(spec.check.method.empty());  // no second run needed with a published reference
  const studies::WpResult r = studies::workPrecision(*scene, spec);
  REQUIRE(r.rows.size() == 3);
  for (int k = 0; k < 2; ++k) {  // explicit Euler: z_n = z0 - g t (t - h) / 2
    const double h = 0.01 / std::pow(2.0, k);
    CHECK(r.rows[static_cast<std::size_t>(k)].error.final == Approx(9.81 * 1.0 * h / 2).epsilon(1e-9));
    CHECK(r.rows[static_cast<std::size_t>(k)].error.max == Approx(9.81 * 1.0 * h / 2).epsilon(1e-9));
  }
  CHECK(r.rows[2].error.max < 1e-10);  // RK4 integrates a quadratic exactly
}

TEST_CASE("a reference file is interpolated onto the grid and refused when it lacks a channel or the time span") {
  testing::SceneDir dir;
  studies::WpSpec spec;
  spec.channels = {"block.z"};
  spec.interval = 0.25;
  spec.until = 1.0;
  // two rows: linear in between
  const auto file = dir.write("line.csv", "time,block.z[m]\n0,0\n1,2\n").string();
  const studies::WpSeries s = studies::readReferenceSeries(file, spec);
  REQUIRE(s.values.size() == 5);
  CHECK(s.values[1][0] == Approx(0.5));
  CHECK(s.values[4][0] == Approx(2.0));

  const auto noChannel = dir.write("other.csv", "time,block.y[m]\n0,0\n1,2\n").string();
  CHECK_THROWS_WITH(studies::readReferenceSeries(noChannel, spec),
                    Catch::Contains("other.csv") && Catch::Contains("no column for the error channel 'block.z'"));
  const auto shortSpan = dir.write("short.csv", "time,block.z\n0,0\n0.5,1\n").string();
  CHECK_THROWS_WITH(studies::readReferenceSeries(shortSpan, spec),
                    Catch::Contains("short.csv") && Catch::Contains("not the grid time"));
  const auto bad = dir.write("bad.csv", "time,block.z\n0,0\n1,x\n").string();
  CHECK_THROWS_WITH(studies::readReferenceSeries(bad, spec), Catch::Contains("bad.csv:3: expected numbers"));
}
