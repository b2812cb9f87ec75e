// RAOs measured in the time domain (regular_wave_run.hpp): the rigid-body mass about the origin
// against its hand form; in a long wave (w = 0.6 rad/s, wavelength 171 m against a 6 m barge) the
// heave RAO tends to 1 (the barge follows the surface) and its phase to 0; bad modes are refused.
// The comparison with the frequency domain at shorter waves is frequency_domain_test's.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "forces/hydro/regular_wave_run.hpp"
#include "td_fixtures.hpp"

using namespace yardsim;
using namespace yardsim::forces::hydro;
using namespace yardsim::forces::hydro::test;

TEST_CASE("the rigid-body mass about the origin in naval order") {
  RigidBody b;
  b.mass = 2.0;
  b.com = Vector3(0.1, -0.2, 0.3);
  b.inertiaCom = Vector3(1.0, 2.0, 3.0).asDiagonal();
  const auto M = rigidBodyMass(b);
  // (hand form) => [m I, -m [c]x; m [c]x, I_c - m [c]x [c]x]
  Eigen::Matrix3d c;
  c << 0.0, -0.3, -0.2, 0.3, 0.0, -0.1, 0.2, 0.1, 0.0;
  CHECK((M.topLeftCorner<3, 3>() - 2.0 * Eigen::Matrix3d::Identity()).norm() < 1e-14);
  CHECK((M.topRightCorner<3, 3>() + 2.0 * c).norm() < 1e-14);
  CHECK((M.bottomLeftCorner<3, 3>() - 2.0 * c).norm() < 1e-14);
  CHECK((M.bottomRightCorner<3, 3>() - (b.inertiaCom - 2.0 * c * c)).norm() < 1e-14);
}

TEST_CASE("a barge in a long wave heaves with the surface", "[long]") {
  const double omega = 0.6;
  const auto model = std::make_shared<const RankineTdModel>(
      BoxBarge{}.hull(), dynamics::Transform{}, BoxBarge::settings(omega));
  RegularWaveRun run;
  run.omega = omega;
  run.heading = 0.5 * std::numbers::pi;
  run.amplitude = 0.05;
  run.periods = 16;
  run.analysisPeriods = 6;
  run.freeModes = {2};
  const auto rao = measuredResponse(model, BoxBarge::body(), BoxBarge::restoring(), run);
  INFO("heave RAO " << std::abs(rao[2]) << " at phase " << std::arg(rao[2]));
  // (measured: 1.0005 at -0.037 rad)
  CHECK(std::abs(rao[2]) == Approx(1.0).epsilon(0.03));
  CHECK(std::abs(std::arg(rao[2])) < 0.1);
  CHECK(rao[0] == std::complex<double>(0.0));
  run.freeModes = {3, 2};
  CHECK_THROWS_AS(measuredResponse(model, BoxBarge::body(), BoxBarge::restoring(), run),
                  std::invalid_argument);
}
