// The pre-run checks of a time-domain Rankine set-up: quiet for a sound one, and a message with
// the numbers for a hull reaching the damping zone, a free-surface panel longer than a tenth of
// the shortest wave, and a step above the emp limit.
#include <catch2/catch.hpp>

#include "forces/hydro/td_checks.hpp"
#include "forces/hydro/wetted_surface.hpp"
#include "td_fixtures.hpp"

using namespace yardsim::forces::hydro;
using namespace yardsim::forces::hydro::test;

TEST_CASE("a hull inside the undamped free surface passes and one reaching the zone is named") {
  const PanelMesh hull = cubeSphere(1.0, 6);
  FreeSurfaceSettings s = hemisphereSettings(1.0).freeSurface;
  CHECK_FALSE(checkTruncation(hull, s).has_value());
  s.truncationRadius = 4.0;
  s.dampingWidth = 3.5;
  const auto m = checkTruncation(hull, s);
  REQUIRE(m.has_value());
  CHECK_THAT(*m, Catch::Contains("reaches 1 m") && Catch::Contains("truncation radius 4 m") &&
                     Catch::Contains("= 0.5 m"));
}

TEST_CASE("free-surface panels longer than a tenth of the shortest wave are named") {
  const RankineTdSettings s =
      hemisphereSettings(1.0);  // 10 panels per wavelength of ka = 1 radially
  const FreeSurfaceMesh fs = buildFreeSurface(wettedSurface(cubeSphere(1.0, 6)), s.freeSurface);
  // the azimuthal panel size far out (24 around) is the largest: a long shortest wave passes
  CHECK_FALSE(checkPanelSize(fs, s.freeSurface, 12.0).has_value());
  const auto m = checkPanelSize(fs, s.freeSurface, 2.0);
  REQUIRE(m.has_value());
  CHECK_THAT(*m, Catch::Contains("more than a tenth of the shortest wave (6.243 m at T = 2 s)"));
}

TEST_CASE("a step above the emp limit is named with the limit") {
  EmpLimit limit;
  limit.lambdaMax = 12.0;
  limit.dtMax = 2.0 / std::sqrt(kG * 12.0);
  limit.smallestPanel = 0.25;
  CHECK_FALSE(checkEmpStep(limit, 0.99 * limit.dtMax).has_value());
  const auto m = checkEmpStep(limit, 0.2);
  REQUIRE(m.has_value());
  CHECK_THAT(*m, Catch::Contains("0.2 s is above the emp limit 0.1844 s") &&
                     Catch::Contains("lambda_max 12 1/m"));
}
