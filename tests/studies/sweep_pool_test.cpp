// Cases in child processes: run N at a time, a case past case_timeout killed and recorded, a
// failing case recorded with its diagnosis while the others go on.
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>

#include "studies/sweep_pool.hpp"
#include "support/scene_files.hpp"
#include "support/test_paths.hpp"

using namespace yardsim::studies;

namespace {
const std::string kScene =
    std::string(YARDSIM_SOURCE_DIR) + "/tests/studies/data/pendulum_sweep/scene.yaml";

// (vary block, time-out) => the spec of a sweep file over the tests' pendulum
SweepSpec spec(const yardsim::testing::SceneDir& dir, const std::string& vary,
               const std::string& extra = "") {
  yardsim::models::Diagnostics d;
  SweepSpec s =
      readSweepSpec(dir.write("sweep.yaml", "sweep:\n  scene: " + kScene + "\n  vary: " + vary +
                                                "\n  collect: [max(pendulum.joint0.q)]\n" + extra),
                    d);
  INFO(d.report());
  REQUIRE_FALSE(d.hasErrors());
  return s;
}
}  // namespace

TEST_CASE("The pool runs every case in its own process and records each") {
  yardsim::testing::SceneDir dir;
  const SweepSpec s = spec(dir, "{speed_deg: [2, 4, 6, 8]}");
  std::vector<CaseRecord> done;
  runLocalPool(s, expandCases(s), dir.path() / "out",
               {2, 5, [&](const CaseRecord& r) { done.push_back(r); }});
  REQUIRE(done.size() == 4);
  for (const auto& r : done) {
    CHECK(r.status == "ok");
    CHECK(r.rank == 5);
    CHECK(readCaseRecord(caseDir(dir.path() / "out", r.id) / "case.yaml"));
  }
}

TEST_CASE(
    "A case past its case_timeout is killed and recorded, a failing one too, and the rest run") {
  yardsim::testing::SceneDir dir;
  // dt 1e-7 s: sixty million steps, far beyond 3 s; dt 0: refused by the scene; dt 0.5: RK4
  // unstable (a numerical failure); dt 0.002: runs well within 3 s (also under the sanitizers)
  const SweepSpec s = spec(dir, "{dt: [1.0e-7, 0, 0.5, 0.002]}", "  case_timeout: 3\n");
  std::vector<CaseRecord> done(4);
  const auto start = std::chrono::steady_clock::now();
  runLocalPool(s, expandCases(s), dir.path() / "out",
               {4, 0, [&](const CaseRecord& r) { done[r.id] = r; }});
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CHECK(wall < 15.0);
  CHECK(done[0].status == "timeout");
  CHECK_THAT(done[0].message, Catch::Contains("case_timeout of 3 s"));
  CHECK(done[0].wall >= 3.0);
  CHECK(readCaseRecord(caseDir(dir.path() / "out", 0) / "case.yaml")->status == "timeout");
  CHECK(done[1].status == "refused");
  CHECK_THAT(done[1].message, Catch::Contains("dt"));
  CHECK(done[2].status == "failed");
  CHECK_THAT(done[2].message, Catch::Contains("the integration is unstable"));
  CHECK(std::isfinite(done[2].collected[0]));  // from what was recorded until the failure
  CHECK(done[3].status == "ok");
}
