// Regression test of examples/ku2014_loop (Ku et al. 2014, Fig. 3): the loop stays closed, the
// slider obeys the slider-crank kinematics, energy is conserved, and the recorded accelerations
// agree with finite differences of the recorded velocities.
#include <catch2/catch.hpp>
#include <cmath>

#include "scene/assembler.hpp"
#include "run/runner.hpp"
#include "scene/scene_loader.hpp"
#include "support/csv_file.hpp"
#include "support/scene_files.hpp"
#include "support/test_paths.hpp"

using namespace yardsim;

TEST_CASE("Ku 2014 verification model: closed loop, slider-crank kinematics, energy") {
  auto scene = scene::loadSceneOrThrow(std::string(YARDSIM_SOURCE_DIR) + "/examples/ku2014_loop/scene.yaml");
  auto root = scene::assemble(*scene);
  testing::SceneDir out;
  run::runScene(*scene, *root, {out.path(), scene->until, {}, {}, 0.1});
  const testing::CsvFile csv((out.path() / "timeseries.csv").string());
  REQUIRE(csv.rows.size() == 201);
  const int q1 = csv.column("mechanism.revolute1.q[rad]");
  const int v1 = csv.column("mechanism.revolute1.v[rad/s]");
  const int a1 = csv.column("mechanism.revolute1.a[rad/s^2]");
  const int z = csv.column("mechanism.body3.z[m]");
  const int res = csv.column("mechanism.loop_residual[m]");
  const int e = csv.column("mechanism.energy[J]");
  REQUIRE(std::min({q1, v1, a1, z, res, e}) > 0);
  const double r = 1.0, l = 2.0, e0 = csv.rows[0][e];
  double worstResidual = 0, worstKinematics = 0, worstEnergy = 0, worstAccel = 0;
  for (std::size_t k = 0; k < csv.rows.size(); ++k) {
    const auto& row = csv.rows[k];
    worstResidual = std::max(worstResidual, row[res]);
    const double c = std::cos(row[q1]);
    worstKinematics = std::max(worstKinematics,
                               std::abs(row[z] - (-r * std::sin(row[q1]) + std::sqrt(l * l - r * r * c * c))));
    worstEnergy = std::max(worstEnergy, std::abs(row[e] - e0));
    if (k > 0 && k + 1 < csv.rows.size()) {  // central difference of v, O(h^2) = O(2.5e-5)
      const double fd = (csv.rows[k + 1][v1] - csv.rows[k - 1][v1]) / (csv.rows[k + 1][0] - csv.rows[k - 1][0]);
      worstAccel = std::max(worstAccel, std::abs(fd - row[a1]) / (1.0 + std::abs(row[a1])));
    }
  }
  INFO("residual " << worstResidual << " kinematics " << worstKinematics << " energy "
                   << worstEnergy << " accel " << worstAccel);
  CHECK(csv.rows.back()[q1] > 1.0);  // the crank swung through a large angle
  CHECK(worstResidual <= 1e-10);
  CHECK(worstKinematics <= 1e-9);
  CHECK(worstEnergy <= 1e-8 * std::abs(e0));
  CHECK(worstAccel <= 1e-2);
}
