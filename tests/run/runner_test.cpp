#include "run/runner.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <iterator>

#include "scene/assembler.hpp"
#include "models/numerical_error.hpp"
#include "scene/scene_loader.hpp"
#include "support/csv_file.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;

namespace {
std::string springScene(double dt, const std::string& method, double until) {
  return "schema_version: 1\ncomponents:\n  s: {type: spring_mass, params: {mass: 1, stiffness: 1, "
         "x0: 1, dt: " + std::to_string(dt) + ", method: " + method +
         ", blowup_limit: 1000}}\nrecord: {interval: " + std::to_string(dt) +
         ", channels: ['s.*']}\nuntil: " + std::to_string(until) + "\n";
}
}  // namespace

TEST_CASE("samples land on the record grid and the sinks asked for are written") {
  testing::SceneDir dir;
  auto scene = scene::loadSceneOrThrow(dir.write("s.yaml", springScene(0.05, "rk4", 2.0)));
  auto root = scene::assemble(*scene);
  run::RunOptions opt{dir.path() / "out", scene->until, {"jsonl", "csv"}, {}, 0.1, 2000};
  const auto r = run::runScene(*scene, *root, opt);
  CHECK(r.tEnd == 2.0);
  CHECK(r.samples == 41);
  CHECK(std::filesystem::exists(dir.path() / "out/trace.jsonl"));
  CHECK(std::filesystem::exists(dir.path() / "out/trace.csv"));
  CHECK_FALSE(std::filesystem::exists(dir.path() / "out/trace.json"));  // not asked for
  const testing::CsvFile csv((dir.path() / "out/timeseries.csv").string());
  REQUIRE(csv.rows.size() == 41);
  const int x = csv.column("s.x[m]");
  REQUIRE(x > 0);
  for (const auto& row : csv.rows) CHECK(row[x] == Approx(std::cos(row[0])).margin(1e-6));
}

TEST_CASE("a profiled run writes the same files and books its output time apart") {
  testing::SceneDir dir;
  auto scene = scene::loadSceneOrThrow(dir.write("s.yaml", springScene(0.01, "rk4", 5.0)));
  auto read = [](const std::filesystem::path& f) {
    std::ifstream in(f, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  run::RunResult r[2];
  for (int profiled = 0; profiled < 2; ++profiled) {
    auto root = scene::assemble(*scene);
    run::RunOptions opt{dir.path() / ("out" + std::to_string(profiled)), scene->until, {"jsonl"}, {}, 0.1, 2000};
    opt.profile = profiled == 1;
    r[profiled] = run::runScene(*scene, *root, opt);
  }
  CHECK(read(dir.path() / "out0/trace.jsonl") == read(dir.path() / "out1/trace.jsonl"));
  CHECK(read(dir.path() / "out0/timeseries.csv") == read(dir.path() / "out1/timeseries.csv"));
  for (const auto& x : r) {
    CHECK(x.outputSeconds > 0.0);  // 501 rows written
    CHECK(x.simulateSeconds > 0.0);
  }
}

TEST_CASE("a run that blows up stops with a diagnosis and keeps what it recorded") {
  testing::SceneDir dir;
  // RK4 on an undamped spring is unstable beyond omega*dt = 2.83: dt = 3 grows every step
  auto scene = scene::loadSceneOrThrow(dir.write("s.yaml", springScene(3.0, "rk4", 1000.0)));
  auto root = scene::assemble(*scene);
  run::RunOptions opt{dir.path() / "out", scene->until, {}, {}, 0.1, 2000};
  try {
    run::runScene(*scene, *root, opt);
    FAIL("expected a numerical failure");
  } catch (const models::NumericalError& e) {
    const std::string msg = e.what();
    CHECK_THAT(msg, Catch::Contains("spring_mass 's'") && Catch::Contains("at t = "));
    CHECK_THAT(msg, Catch::Contains("suggestion: a smaller dt"));
  }
  const testing::CsvFile csv((dir.path() / "out/timeseries.csv").string());
  REQUIRE(csv.rows.size() >= 3);  // every sample before the failure is on disk
  const auto& last = csv.rows.back();
  CHECK(std::abs(last[1]) <= 1000.0);
  CHECK(std::abs(last[1]) > 1.0);  // it was growing
}

TEST_CASE(
    "the last valid sample before a blow-up is on disk and the failure is dated by the failed "
    "state") {
  testing::SceneDir dir;
  // issue 14: the row at the time of the last valid state was lost (CSV ending one step early)
  const double h = 3.0;
  auto scene = scene::loadSceneOrThrow(dir.write("s.yaml", springScene(h, "rk4", 1000.0)));
  auto root = scene::assemble(*scene);
  run::RunOptions opt{dir.path() / "out", scene->until, {}, {}, 0.1, 2000};
  double failedAt = -1.0;
  try {
    run::runScene(*scene, *root, opt);
    FAIL("expected a numerical failure");
  } catch (const models::NumericalError& e) {
    const std::string msg = e.what();
    failedAt = std::stod(msg.substr(msg.find("at t = ") + 7));
  }
  const testing::CsvFile csv((dir.path() / "out/timeseries.csv").string());
  const int x = csv.column("s.x[m]"), v = csv.column("s.v[m/s]");
  REQUIRE(x > 0);
  REQUIRE(v > 0);
  const auto& last = csv.rows.back();
  CHECK(last[0] + h == Approx(failedAt));  // the state before the one that failed
  // cross-check: the same spring with a bound it never reaches gives that row at that time (the
  // row is the state the model had committed there, not a stale or a failed one)
  std::string wide = springScene(h, "rk4", failedAt);
  wide.replace(wide.find("blowup_limit: 1000"), 18, "blowup_limit: 1e12");
  auto scene2 = scene::loadSceneOrThrow(dir.write("wide.yaml", wide));
  auto root2 = scene::assemble(*scene2);
  run::runScene(*scene2, *root2, {dir.path() / "wide", scene2->until, {}, {}, 0.1, 2000});
  const testing::CsvFile full((dir.path() / "wide/timeseries.csv").string());
  const auto same = std::find_if(full.rows.begin(), full.rows.end(),
                                 [&](const auto& row) { return row[0] == last[0]; });
  REQUIRE(same != full.rows.end());
  CHECK(last[x] == (*same)[x]);
  CHECK(last[v] == (*same)[v]);
  CHECK(std::abs(last[x]) <= 1000.0);  // valid: inside the blow-up limit
}

namespace {
// never lets time advance after t = 1 (an illegitimate DEVS model)
struct Spin {
  int n = 0;
};
std::ostream& operator<<(std::ostream& os, const Spin& s) { return os << s.n; }
class Spinner final : public devs::Atomic<Spin> {
 public:
  Spinner() : devs::Atomic<Spin>("spin", Spin{}) {}

 protected:
  devs::Time timeAdvance(const Spin& s) const override { return s.n == 0 ? 1.0 : 0.0; }
  void output(const Spin&) const override {}
  void internalTransition(Spin& s) const override { ++s.n; }
  void externalTransition(Spin&, devs::Time) const override {}
};
}  // namespace

TEST_CASE("a zero-time loop stops the run with a diagnosis naming the model, and run.json says failed") {
  testing::SceneDir dir;
  auto scene = scene::loadSceneOrThrow(dir.write("s.yaml", springScene(0.05, "rk4", 2.0)));
  devs::Coupled root("root");
  root.add<Spinner>();
  run::RunOptions opt{dir.path() / "out", 10.0, {"jsonl"}, {}, 0.1, 2000};
  opt.maxTransitionsPerInstant = 500;
  CHECK_THROWS_WITH(run::runScene(*scene, root, opt),
                    Catch::Contains("more than 500 transitions at t = 1") && Catch::Contains("'root.spin'"));
  std::ifstream json(dir.path() / "out/run.json");
  const std::string summary((std::istreambuf_iterator<char>(json)), std::istreambuf_iterator<char>());
  CHECK(summary.find("\"status\":\"failed\"") != std::string::npos);
  CHECK(std::filesystem::file_size(dir.path() / "out/trace.jsonl") < 1000000);  // bounded, not gigabytes
}
