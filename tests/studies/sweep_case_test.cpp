// One case in this process: the scene run with the case's params, its scalars collected from
// what it recorded, its record on disk; a collect glob no recorded channel matches refused.
#include <catch2/catch.hpp>
#include <cmath>

#include "studies/sweep_case.hpp"
#include "support/csv_file.hpp"
#include "support/scene_files.hpp"
#include "support/test_paths.hpp"

using namespace yardsim::studies;

namespace {
const std::string kData = std::string(YARDSIM_SOURCE_DIR) + "/tests/studies/data/pendulum_sweep/";

// () => the tests' pendulum sweep
SweepSpec pendulum() {
  yardsim::models::Diagnostics d;
  SweepSpec s = readSweepSpec(kData + "sweep.yaml", d);
  INFO(d.report());
  REQUIRE_FALSE(d.hasErrors());
  return s;
}
}  // namespace

TEST_CASE("A case runs its scene with its params and collects from its recorded channels") {
  yardsim::testing::SceneDir dir;
  const SweepSpec s = pendulum();
  const SweepCase c = expandCases(s)[7];  // speed 8 deg/s, link 2 of 1.0 kg
  REQUIRE(c.values == std::vector<double>{8, 1.0});
  const CaseRecord r = runCase(s, c, dir.path(), 3);
  INFO(r.message);
  REQUIRE(r.status == "ok");
  CHECK(r.tEnd == 6.0);
  CHECK(r.rank == 3);
  CHECK(r.wall > 0.0);
  const yardsim::testing::CsvFile csv((caseDir(dir.path(), 7) / "timeseries.csv").string());
  const int q0 = csv.column("pendulum.joint0.q[rad]"), q1 = csv.column("pendulum.joint1.q[rad]");
  double max0 = -1e300;
  for (const auto& row : csv.rows) max0 = std::max(max0, row[q0]);
  CHECK(r.collected[0] == max0);
  CHECK(r.collected[1] == csv.rows.back()[q1]);
  // joint 0 reaches 45 deg at 5.625 s, then actor 3 turns it on at 8 deg/s: 48 deg at 6 s
  CHECK(r.collected[0] == Approx(48.0 * M_PI / 180.0).margin(1e-3));
  const auto back = readCaseRecord(caseDir(dir.path(), 7) / "case.yaml");
  REQUIRE(back);
  CHECK(back->collected == r.collected);
  CHECK(back->values == r.values);
  CHECK(back->wall == r.wall);
  CHECK_FALSE(std::filesystem::exists(caseDir(dir.path(), 7) / "case.yaml.tmp"));
}

TEST_CASE("A case record keeps NaN and the diagnosis, and a torn one reads as missing") {
  yardsim::testing::SceneDir dir;
  CaseRecord r;
  r.id = 12;
  r.values = {0.1, 3};
  r.status = "failed";
  r.message = "numerical failure: NaN in 'link2' at t = 0.5 s:\n  use a smaller step";
  r.collected = {std::nan(""), 1.0 / 3.0};
  writeCaseRecord(r, dir.path() / "case.yaml");
  const auto back = readCaseRecord(dir.path() / "case.yaml");
  REQUIRE(back);
  CHECK(back->message == r.message);
  CHECK(std::isnan(back->collected[0]));
  CHECK(back->collected[1] == 1.0 / 3.0);
  dir.write("torn.yaml", "id: 12\nvalues: [0.1, 3]\nstatus: ok\nmess");
  CHECK_FALSE(readCaseRecord(dir.path() / "torn.yaml"));
  CHECK_FALSE(readCaseRecord(dir.path() / "absent.yaml"));
}

TEST_CASE("At the door a collect glob that matches no recorded channel is an error") {
  yardsim::testing::SceneDir dir;
  dir.write("sweep.yaml", "sweep:\n  scene: " + kData +
                              "scene.yaml\n  vary: {speed_deg: [4]}\n"
                              "  collect: [max(pendulum.joint0.q), max(pendulum.hook.z)]\n");
  yardsim::models::Diagnostics d;
  const SweepSpec s = readSweepSpec(dir.path() / "sweep.yaml", d);
  REQUIRE_FALSE(d.hasErrors());
  const std::string report = checkCase(s, expandCases(s)[0]).report();
  CHECK_THAT(report, Catch::Contains(
                         ":4:37: error: sweep.collect.max(pendulum.hook.z): no recorded channel"));
  CHECK_THAT(report, !Catch::Contains("joint0"));
}
