// examples/andrews against the published reference solution of Andrews' squeezing mechanism
// (Hairer & Wanner, Solving ODEs II, sec. VII.7; the Bari test set's "andrews" problem): the
// seven angles and their rates at t = 0.03 s to six significant digits, the loops closed, the
// spring compressed there, and the energy balance (the drive torque's work) closed.
#include <catch2/catch.hpp>
#include <cmath>

#include "run/runner.hpp"
#include "scene/assembler.hpp"
#include "scene/scene_loader.hpp"
#include "support/csv_file.hpp"
#include "support/scene_files.hpp"
#include "support/test_paths.hpp"

using namespace yardsim;

TEST_CASE("andrews: the scene reproduces Hairer and Wanner's positions at t = 0.03 s") {
  auto scene =
      scene::loadSceneOrThrow(std::string(YARDSIM_SOURCE_DIR) + "/examples/andrews/scene.yaml");
  auto root = scene::assemble(*scene);
  testing::SceneDir out;
  run::runScene(*scene, *root, {out.path(), 0.03, {}, {}, 0.1});
  const testing::CsvFile csv((out.path() / "timeseries.csv").string());
  REQUIRE(!csv.rows.empty());
  const auto& r = csv.rows.back();
  REQUIRE(r[0] == Approx(0.03).margin(1e-12));
  auto at = [&](const std::string& name) {
    const int k = csv.column(name);
    REQUIRE(k > 0);
    return r[k];
  };
  const double tol = 5e-7;  // six significant digits
  CHECK(at("beta.q[rad]") == Approx(0.1581077119629904e+02).epsilon(tol));
  CHECK(at("theta.q[rad]") == Approx(-0.1575637105984298e+02).epsilon(tol));
  CHECK(at("gamma.q[rad]") == Approx(0.4082224013073101e-01).epsilon(tol));
  CHECK(at("phi.q[rad]") == Approx(-0.5347301163226948e+00).epsilon(tol));
  CHECK(at("delta.q[rad]") == Approx(0.5244099658805304e+00).epsilon(tol));
  CHECK(at("omega.q[rad]") == Approx(0.5347301163226948e+00).epsilon(tol));
  CHECK(at("epsilon.q[rad]") == Approx(0.1048080741042263e+01).epsilon(tol));
  CHECK(at("beta.v[rad/s]") == Approx(0.1139920302151208e+04).epsilon(tol));
  CHECK(at("theta.v[rad/s]") == Approx(-0.1424379294994111e+04).epsilon(tol));
  CHECK(at("gamma.v[rad/s]") == Approx(0.1103291221937134e+02).epsilon(tol));
  CHECK(at("phi.v[rad/s]") == Approx(0.1929337464421385e+02).epsilon(tol));
  CHECK(at("delta.v[rad/s]") == Approx(0.5735699284790808e+00).epsilon(tol));
  CHECK(at("omega.v[rad/s]") == Approx(-0.1929337464421385e+02).epsilon(tol));
  CHECK(at("epsilon.v[rad/s]") == Approx(0.3231791658026955e+00).epsilon(tol));
  CHECK(at("mechanics.loop_residual[m]") <= 1e-10);
  // (the spring at 0.03 s) => shorter than its free length: it pushes
  CHECK(at("spring.length[m]") < 0.07785);
  CHECK(at("spring.force[N]") < 0.0);
  // (energy: kinetic + spring; work: the torque's) => balance closed against the work done
  double worst = 0;
  const int balance = csv.column("mechanics.energy_balance[J]");
  REQUIRE(balance > 0);
  for (const auto& row : csv.rows)
    worst = std::max(worst, std::abs(row[balance] - csv.rows[0][balance]));
  CHECK(worst < 1e-6 * 0.033 * std::abs(at("beta.q[rad]")));
}
