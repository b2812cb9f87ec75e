// OCIMF-style flow loads: the coefficient table (mirrored and full), the force and yaw moment of
// a beam and a head flow in the body's heading axes, the relative velocity (a body drifting with
// the flow feels nothing), the power, and a gusty wind's drag following its instantaneous speed.
#include <catch2/catch.hpp>

#include <cmath>

#include "dynamics/rotation.hpp"
#include "force_rig.hpp"
#include "forces/current_load.hpp"
#include "forces/wind_load.hpp"

using namespace yardsim;
using namespace yardsim::forces;
using namespace yardsim::forces::testing;

namespace {
constexpr double kDeg = M_PI / 180;
dynamics::Model freeBody() {
  dynamics::ModelBuilder b;
  b.setGravity(Vector3::Zero());
  b.addBody("ship", "world", dynamics::Joint::free(), dynamics::Transform::identity(),
            dynamics::boxInertia(1e6, Vector3(100, 20, 10)));
  return b.build();
}
}  // namespace

TEST_CASE("coefficient tables: linear, mirrored past 180 deg, or full circle, and the default") {
  const FlowCoefficients half({0, 90 * kDeg, 180 * kDeg}, {-0.8, 0.0, 0.6}, {0.0, -0.9, 0.0}, {0.0, 0.1, 0.0});
  auto c = half.at(45 * kDeg);
  CHECK(c[0] == Approx(-0.4));
  CHECK(c[1] == Approx(-0.45));
  CHECK(c[2] == Approx(0.05));
  c = half.at(-45 * kDeg);  // = 315 deg: the mirror of 45 deg
  CHECK(c[0] == Approx(-0.4));
  CHECK(c[1] == Approx(0.45));
  CHECK(c[2] == Approx(-0.05));
  const FlowCoefficients full({0, 180 * kDeg, 360 * kDeg}, {1, 3, 1}, {0, 2, 0}, {0, 0, 0});
  CHECK(full.at(270 * kDeg)[0] == Approx(2.0));
  CHECK(full.at(270 * kDeg)[1] == Approx(1.0));
  const FlowCoefficients plain;
  CHECK(plain.at(0.0)[0] == Approx(-1.0));
  CHECK(plain.at(90 * kDeg)[1] == Approx(-1.0));
  CHECK_THROWS_AS(FlowCoefficients({0, 90 * kDeg}, {0, 0}, {0, 0}, {0, 0}), std::invalid_argument);
  CHECK_THROWS_AS(FlowCoefficients({0, 180 * kDeg, 90 * kDeg}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}), std::invalid_argument);
  CHECK_THROWS_AS(FlowCoefficients({0, 180 * kDeg}, {0, 0}, {0}, {0, 0}), std::invalid_argument);
}

TEST_CASE("wind on a ship heading 30 deg: force in the heading axes, yaw moment, relative velocity") {
  const dynamics::Model model = freeBody();
  WindProperties wp;
  wp.speed = 25.0;
  wp.profile = WindProfileKind::Uniform;
  wp.direction = (30.0 - 90.0) * kDeg;  // blowing towards the ship's starboard: from port (+y)
  auto wind = std::make_shared<const WindField>(wp);
  const FlowAreas areas{400.0, 1500.0, 100.0};
  const FlowCoefficients table({0, 90 * kDeg, 180 * kDeg}, {-0.8, 0.0, 0.6}, {0.0, -0.9, 0.0}, {0.0, 0.1, 0.0});
  WindLoad load("wind", model, 1, Vector3(5, 0, 12), areas, table, wind);
  Rig r(model, {&load});
  const dynamics::Matrix3 R = dynamics::axisRotation(Vector3::UnitZ(), 30 * kDeg);
  double quat[4];
  dynamics::matrixToQuaternion(R, quat);
  r.q << 0, 0, 0, quat[0], quat[1], quat[2], quat[3];
  const FlowLoadState s = load.load(r.stage());
  const double q = 0.5 * 1.226 * 25.0 * 25.0;
  CHECK(s.speed == Approx(25.0));
  CHECK(s.angle == Approx(90 * kDeg));
  CHECK((s.force - R * Vector3(0, -0.9 * q * 1500, 0)).norm() < 1e-9 * q * 1500);
  CHECK(s.yawMoment == Approx(0.1 * q * 1500 * 100));
  // evaluate: the force at the point plus the yaw moment, about the world origin
  dynamics::ExternalForces f(model);
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(6);
  load.evaluate(r.stage(), f, tau);
  const Vector3 p_W = R * Vector3(5, 0, 12);
  CHECK((f.worldFrame(1).head<3>() - (p_W.cross(s.force) + Vector3(0, 0, s.yawMoment))).norm() < 1e-6);
  // (the ship drifting with the wind) => no relative flow, no force
  r.v.tail<3>() = R.transpose() * wind->velocity(p_W, 0.0);
  CHECK(load.load(r.stage()).force.norm() < 1e-9);
  // (the ship moving against a calm) => power F . v < 0, and the balance closes
  WindProperties still = wp;
  still.speed = 0.0;
  WindLoad drag("drag", model, 1, Vector3(5, 0, 12), areas, table, std::make_shared<const WindField>(still));
  Rig d(model, {&drag});
  d.q = r.q;
  d.v << 0.0, 0.0, 0.02, 3.0, 1.0, 0.0;
  CHECK(drag.power(d.stage()) < 0.0);
  const Rig::Balance b = d.energyBalance(0.01, 400);
  CHECK(b.maxError < 1e-6 * b.maxWork);
}

TEST_CASE("a gusty wind's drag follows the instantaneous speed squared") {
  const dynamics::Model model = freeBody();
  WindProperties wp;
  wp.speed = 15.0;
  wp.profile = WindProfileKind::Npd;
  wp.direction = -90 * kDeg;  // towards -y: a beam wind from port on a ship heading +x
  wp.gusts = GustProperties{};
  auto wind = std::make_shared<const WindField>(wp);
  const FlowAreas areas{400.0, 1500.0, 100.0};
  WindLoad load("wind", model, 1, Vector3(5, 0, 12), areas, FlowCoefficients(), wind);
  Rig r(model, {&load});
  r.q << 0, 0, 0, 1, 0, 0, 0;
  double lo = 1e300, hi = 0;
  for (double t = 0; t < 600; t += 7.3) {
    r.t = t;
    const FlowLoadState s = load.load(r.stage());
    // (the speed at the point's 12 m: the mean there plus the gust at t) => F_y = -1/2 rho V^2 A_lat C_y
    const double V = wind->speedAt(12.0) + wind->gust(t);
    CHECK(s.speed == Approx(V).epsilon(1e-12));
    CHECK(s.force.y() == Approx(-0.5 * 1.226 * V * V * 1500.0).epsilon(1e-12));
    CHECK(std::abs(s.force.x()) < 1e-9 * std::abs(s.force.y()));
    lo = std::min(lo, -s.force.y());
    hi = std::max(hi, -s.force.y());
  }
  // (the gust) => the force swings by more than a fifth of its mean level over ten minutes
  const double mean = 0.5 * 1.226 * std::pow(wind->speedAt(12.0), 2) * 1500.0;
  CHECK(hi - lo > 0.2 * mean);
}

TEST_CASE("current load: water density, speed at the point's depth") {
  const dynamics::Model model = freeBody();
  CurrentProperties cp;
  cp.speed = 2.0;
  cp.direction = 0.0;  // towards +x: from astern for a ship heading +x
  cp.profile = {{-20.0, 0.5}, {0.0, 1.0}};
  auto current = std::make_shared<const CurrentField>(cp);
  CurrentLoad load("current", model, 1, Vector3(0, 0, -10), {150.0, 900.0, 100.0}, FlowCoefficients(), current, 1025.0);
  Rig r(model, {&load});
  r.q << 0, 0, 0, 1, 0, 0, 0;
  const FlowLoadState s = load.load(r.stage());
  const double u = 2.0 * 0.75;  // at z = -10
  CHECK(s.speed == Approx(u));
  CHECK(std::abs(s.angle) == Approx(180 * kDeg));
  CHECK(s.force.x() == Approx(0.5 * 1025.0 * u * u * 150.0));  // default C_x(180) = +1: pushed ahead
  CHECK(std::abs(s.force.y()) < 1e-9);
  CHECK_THROWS_AS(CurrentLoad("c", model, 1, Vector3::Zero(), {-1.0, 1.0, 1.0}, FlowCoefficients(), current),
                  std::invalid_argument);
}
