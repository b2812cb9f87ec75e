// The results of a sweep: OUT/cases.csv, OUT/sweep.h5 (read back by h5py, an independent
// reader) and OUT/sweep.html; the plan that keeps OUT to one sweep.
#include <sys/wait.h>
#include <catch2/catch.hpp>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "studies/sweep_collect.hpp"
#include "studies/sweep_pool.hpp"
#include "support/csv_file.hpp"
#include "support/scene_files.hpp"
#include "support/test_paths.hpp"

using namespace yardsim::studies;
namespace fs = std::filesystem;

namespace {
const std::string kData = std::string(YARDSIM_SOURCE_DIR) + "/tests/studies/data/pendulum_sweep/";

// (arguments) => the output of the tests' h5py reader
std::string dump(const std::string& args) {
  const std::string cmd = "timeout -s KILL 60 " + std::string(YARDSIM_PYTHON3) + " " + std::string(YARDSIM_SOURCE_DIR) +
                          "/tests/studies/sweep_h5_dump.py " + args + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  REQUIRE(p);
  std::string out;
  char buf[4096];
  while (std::size_t n = fread(buf, 1, sizeof buf, p)) out.append(buf, n);
  const int raw = pclose(p);
  INFO(out);
  REQUIRE((WIFEXITED(raw) && WEXITSTATUS(raw) == 0));
  return out;
}

// (text) => its lines split at commas
std::vector<std::vector<std::string>> cells(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream is(text);
  for (std::string line; std::getline(is, line);) {
    std::vector<std::string> row;
    std::istringstream ls(line);
    for (std::string c; std::getline(ls, c, ',');) row.push_back(c);
    rows.push_back(row);
  }
  return rows;
}
}  // namespace

TEST_CASE("sweep.h5 read by h5py holds the case table of cases.csv and each case's time series") {
  yardsim::testing::SceneDir dir;
  yardsim::models::Diagnostics d;
  const SweepSpec s = readSweepSpec(kData + "sweep.yaml", d);
  REQUIRE_FALSE(d.hasErrors());
  auto cases = expandCases(s);
  cases.resize(4);  // cases 4..8 stay missing
  const fs::path out = dir.path() / "out";
  writePlan(s, out);
  runLocalPool(s, cases, out, {2, 0, {}});
  const auto all = expandCases(s);
  const SweepCounts n = writeSweepResults(s, gatherRecords(s, all, out), out);
  CHECK(n.total == 9);
  CHECK(n.ok == 4);
  CHECK(n.missing == 5);
  CHECK(n.passed == 3);  // speed 4 deg/s stays below 0.5 rad in 6 s, 6 deg/s does not

  // (h5py's table, cases.csv) => the same cells by column name, digit for digit
  const auto h5 = cells(dump((out / "sweep.h5").string() + " table"));
  const auto csv = cells([&] {
    std::ifstream is(out / "cases.csv");
    std::stringstream ss;
    ss << is.rdbuf();
    return ss.str();
  }());
  REQUIRE(h5.size() == 10);
  REQUIRE(csv.size() == 10);
  for (std::size_t c = 0; c < h5[0].size(); ++c) {
    const auto at = std::find(csv[0].begin(), csv[0].end(), h5[0][c]);
    REQUIRE(at != csv[0].end());
    const std::size_t k = static_cast<std::size_t>(at - csv[0].begin());
    for (std::size_t r = 1; r < h5.size(); ++r) {
      INFO(h5[0][c] << " of case " << r - 1 << ": " << h5[r][c] << " and " << csv[r][k]);
      if (h5[0][c] == "status")
        CHECK(h5[r][c] == csv[r][k]);
      else if (h5[r][c] == "nan")
        CHECK(csv[r][k] == "nan");
      else
        CHECK(std::stod(h5[r][c]) == std::stod(csv[r][k]));
    }
  }
  CHECK(h5[5][std::find(h5[0].begin(), h5[0].end(), "status") - h5[0].begin()] == "missing");

  // (h5py's /cases/000002, the case's timeseries.csv) => every sample of every channel
  const auto series = cells(dump((out / "sweep.h5").string() + " series 000002"));
  const yardsim::testing::CsvFile ts((caseDir(out, 2) / "timeseries.csv").string());
  REQUIRE(series.size() == ts.rows.size() + 1);
  for (std::size_t c = 1; c < series[0].size(); ++c) {
    int k = -1;
    for (std::size_t j = 0; j < ts.header.size(); ++j)
      if (ts.header[j].rfind(series[0][c] + "[", 0) == 0) k = static_cast<int>(j);
    REQUIRE(k > 0);
    for (std::size_t r = 0; r < ts.rows.size(); ++r)
      CHECK(std::stod(series[r + 1][c]) == ts.rows[r][k]);
  }
  CHECK(fs::exists(out / "sweep.html"));
}

TEST_CASE("A sweep folder holds one sweep: another sweep file is refused") {
  yardsim::testing::SceneDir dir;
  yardsim::models::Diagnostics d;
  const SweepSpec s = readSweepSpec(kData + "sweep.yaml", d);
  writePlan(s, dir.path() / "out");
  writePlan(s, dir.path() / "out");  // the same sweep again: a resume
  CHECK(planSweepFile(dir.path() / "out") == fs::absolute(kData + "sweep.yaml"));
  SweepSpec other = s;
  other.file = dir.write("other.yaml", "sweep: {}\n");
  CHECK_THROWS_WITH(writePlan(other, dir.path() / "out"),
                    Catch::Contains("holds the results of another sweep"));
}
