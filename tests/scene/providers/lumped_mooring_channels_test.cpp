// The channels of a lumped mooring line (`mooring:` with `model: lumped`,
// scene/providers/mooring_reader.cpp) that a catenary line also has: its fairlead and anchor
// angles, its horizontal tension and its touchdown point, against the quasi-static elastic catenary
// of the same line (forces/lines/catenary.hpp) at rest: a chain touching down on the bed, and one
// fully suspended above it that lifts its anchor, each in a vertical plane at 30 degrees to x.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <string>

#include "forces/lines/catenary.hpp"
#include "support/scene_run.hpp"

using namespace yardsim;

namespace {

// 120 mm studless chain: 282.21 kg/m in air, volume-equivalent diameter 0.216 m, EA 1.2e9 N
constexpr double kMass = 282.21, kDiameter = 0.216, kEA = 1.2e9;
const double kAngle = std::numbers::pi / 6.0;  // the line's plane, from x

// (the chain's length) => its catenary parameters on the bed through the anchor
forces::CatenaryParameters chain(double length) {
  const double w = (kMass - 1025.0 * std::numbers::pi / 4.0 * kDiameter * kDiameter) * 9.81;
  return {length, kEA, w, true, 0.0};
}

// (length, the fairlead's horizontal and vertical span from the anchor at the origin, segments)
// => the chain at rest from the origin on the bed to a fixed post, RK4 below the axial mode
std::string chainScene(double length, double xf, double zf, int segments) {
  const double l = length / segments;
  const double m = kMass + 1025.0 * std::numbers::pi / 4.0 * kDiameter * kDiameter;  // Can = 1
  const double dt = 0.5 * l / std::sqrt(kEA / m);
  return R"(schema_version: 1
integrator: {method: rk4, dt: )" +
         std::to_string(dt) + R"(}
mechanics:
  gravity: [0, 0, -9.81]
  bodies:
    post:
      parent: world
      joint: {type: fixed}
      placement: {xyz: [)" +
         std::to_string(xf * std::cos(kAngle)) + ", " + std::to_string(xf * std::sin(kAngle)) +
         ", " + std::to_string(zf) + R"(]}
      mass: 2.0e5
      inertia: [1, 1, 1]
  mooring:
    line: {model: lumped, anchor: [0, 0, 0], fairlead: {body: post}, length: )" +
         std::to_string(length) + ", EA: " + std::to_string(kEA) +
         ", mass: 282.21, diameter: 0.216, segments: " + std::to_string(segments) + R"(}
record: {interval: 0.1, channels: ["line.*"]}
)";
}

// (csv, channel) => its value in the last row (the line at rest: as in the first)
double last(const testing::CsvFile& csv, const std::string& name) {
  const int k = csv.column(name);
  REQUIRE(k > 0);
  CHECK(csv.rows.front()[k] == Approx(csv.rows.back()[k]).epsilon(1e-6).margin(1e-9));
  return csv.rows.back()[k];
}

// (csv, the catenary's solution) => the horizontal tension is the catenary's HF within the
// tolerance the fairlead tension's (1.5 % at 20 segments: lumped_line_provider_test.cpp) and
// angle's (1 %, above) imply for H = T cos(phi): |dH/H| <= |dT/T| + tan(phi) phi |dphi/phi|; and it
// is the horizontal part of the fairlead force, |f_N| cos(its angle below the horizontal).
// Returns its relative error
double checkHorizontalTension(const testing::CsvFile& csv, const forces::CatenarySolution& c) {
  const double h = last(csv, "line.horizontal_tension[N]"), phi = std::atan2(c.vf, c.hf);
  CHECK(h == Approx(c.hf).epsilon(0.015 + std::tan(phi) * phi * 0.01));
  const double t = last(csv, "line.fairlead_tension[N]");
  CHECK(h == Approx(t * std::cos(last(csv, "line.fairlead_angle[rad]"))).epsilon(1e-12));
  return std::abs(h / c.hf - 1.0);
}

}  // namespace

TEST_CASE("lumped mooring: a chain touching down has the catenary's angles and touchdown") {
  // 314 m from the anchor to a fairlead 300 m away and 39 m up: about a third lies on the bed
  const auto c = forces::solveCatenary(chain(314.0), 300.0, 39.0);
  REQUIRE(c.status == forces::CatenaryStatus::Converged);
  REQUIRE(c.profile == forces::CatenaryProfile::TouchingDown);
  double error20 = 0.0;
  for (int n : {20, 40}) {
    INFO(n << " segments");
    testing::SceneDir dir;
    const auto csv = testing::simulateScene(dir, chainScene(314.0, 300.0, 39.0, n), 0.2);
    REQUIRE(csv.rows.size() >= 2);
    // (angles) => the fairlead's within 1 % (the fairlead tension's tolerance); at the anchor the
    // catenary lies on the bed (0 rad) and so does the chain
    CHECK(last(csv, "line.fairlead_angle[rad]") == Approx(std::atan2(c.vf, c.hf)).epsilon(0.01));
    CHECK(last(csv, "line.anchor_angle[rad]") == Approx(0.0).margin(1e-3));
    // (touchdown) => within one segment of the catenary's, along the line's plane; sharper: the
    // last node within one diameter of the bed lies within a segment before the point where the
    // catenary has risen one diameter (0.5 m for the chain's shape against the catenary's)
    const double d = last(csv, "line.touchdown_distance[m]"), l = 314.0 / n;
    const double w = chain(314.0).weight;
    const double rise = c.hf / w * std::acosh(1.0 + w * kDiameter / c.hf);  // 4.8 m
    CHECK(std::abs(d - c.touchdownX) < l);
    CHECK(d - c.touchdownX < rise + 0.5);
    CHECK(d - c.touchdownX > rise - l - 0.5);
    CHECK(last(csv, "line.touchdown_x[m]") == Approx(d * std::cos(kAngle)).epsilon(1e-6));
    CHECK(last(csv, "line.touchdown_y[m]") == Approx(d * std::sin(kAngle)).epsilon(1e-6));
    // (H) => converging at second order as the segments halve (as the fairlead tension does)
    const double err = checkHorizontalTension(csv, c);
    INFO("horizontal tension's error " << err);
    if (n == 20) error20 = err;
    if (n == 40) CHECK(err < error20 / 4.0);
    // (a frictionless bed and the net weight push vertically, the line is at rest without drag)
    // => every segment carries the same horizontal force: the first one, lying flat on the bed,
    // carries its whole tension horizontally
    CHECK(last(csv, "line.horizontal_tension[N]") ==
          Approx(last(csv, "line.anchor_tension[N]")).epsilon(1e-6));
  }
}

TEST_CASE("lumped mooring: a suspended chain has the catenary's angles and no touchdown") {
  // 226 m to a fairlead 200 m away and 100 m up: taut, it leaves the anchor 10.4 deg up
  const auto c = forces::solveCatenary(chain(226.0), 200.0, 100.0);
  REQUIRE(c.status == forces::CatenaryStatus::Converged);
  REQUIRE(c.profile == forces::CatenaryProfile::Suspended);
  REQUIRE(c.va > 0.1 * c.ha);
  testing::SceneDir dir;
  const auto csv = testing::simulateScene(dir, chainScene(226.0, 200.0, 100.0, 20), 0.2);
  REQUIRE(csv.rows.size() >= 2);
  CHECK(last(csv, "line.fairlead_angle[rad]") == Approx(std::atan2(c.vf, c.hf)).epsilon(0.01));
  CHECK(last(csv, "line.anchor_angle[rad]") == Approx(std::atan2(c.va, c.ha)).epsilon(0.01));
  checkHorizontalTension(csv, c);
  // (nothing on the bed past the anchor) => the touchdown is the anchor, as the catenary's
  CHECK(c.touchdownX == 0.0);
  CHECK(last(csv, "line.touchdown_distance[m]") == 0.0);
  CHECK(last(csv, "line.touchdown_x[m]") == 0.0);
  CHECK(last(csv, "line.touchdown_y[m]") == 0.0);
}
