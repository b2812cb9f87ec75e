#include "run/timeseries_writer.hpp"

#include <catch2/catch.hpp>
#include <fstream>
#include <sstream>

#include "scene/sha256.hpp"
#include "support/csv_file.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;

TEST_CASE("the time series has metadata, a unit-tagged header and exact numbers") {
  testing::SceneDir dir;
  scene::Scene scene;
  scene.file = dir.write("s.yaml", "schema_version: 1\n");
  scene.sha256 = "abc123";
  scene.integrator = "rk4";
  scene.dt = 0.01;
  scene.seed = 42;
  double x = 0.1;
  {
    run::TimeseriesWriter w(dir.path() / "ts.csv", scene,
                            {{"crane1.hoist1.tension", "N", [&] { return x; }},
                             {"pendulum.joint0.q", "rad", [&] { return -x / 3; }}});
    w.sample(0.0);
    x = 1e300;
    w.sample(0.5);
    CHECK(w.rows() == 2);
  }
  const testing::CsvFile csv((dir.path() / "ts.csv").string());
  CHECK(csv.meta.at("yardsim") == run::kVersion);
  CHECK(csv.meta.at("scene_sha256") == "abc123");
  CHECK(csv.meta.at("integrator") == "rk4");
  CHECK(std::stod(csv.meta.at("step")) == 0.01);
  CHECK(csv.meta.at("seed") == "42");
  CHECK(csv.header ==
        std::vector<std::string>{"time[s]", "crane1.hoist1.tension[N]", "pendulum.joint0.q[rad]"});
  REQUIRE(csv.rows.size() == 2);
  CHECK(csv.rows[0][1] == 0.1);  // round-trips exactly
  CHECK(csv.rows[0][2] == -0.1 / 3);
  CHECK(csv.rows[1][0] == 0.5);
  CHECK(csv.rows[1][1] == 1e300);
}

TEST_CASE("rows of channels that hold still or change sign of zero are written exactly") {
  // each row's text against appendCsvNumber of the same values: a channel repeated, one that
  // alternates between 0 and -0, NaN and infinity held, one that changes every row
  testing::SceneDir dir;
  scene::Scene scene;
  scene.file = dir.write("s.yaml", "schema_version: 1\n");
  const std::vector<std::vector<double>> rows = {{1.5, 0.0, std::nan(""), 0.1},
                                                 {1.5, -0.0, std::nan(""), 0.2},
                                                 {1.5, 0.0, HUGE_VAL, 0.1 + 0.2},
                                                 {1.5000000000000002, -0.0, HUGE_VAL, 0.3},
                                                 {1.5000000000000002, -0.0, -HUGE_VAL, 0.3}};
  std::size_t r = 0;
  std::string expected;
  {
    std::vector<run::Channel> channels;
    for (std::size_t c = 0; c < 4; ++c)
      channels.push_back({"c" + std::to_string(c), "1", [&rows, &r, c] { return rows[r][c]; }});
    run::TimeseriesWriter w(dir.path() / "ts.csv", scene, channels);
    for (r = 0; r < rows.size(); ++r) {
      w.sample(static_cast<double>(r));
      run::appendCsvNumber(expected, static_cast<double>(r));
      for (double v : rows[r]) {
        expected += ',';
        run::appendCsvNumber(expected, v);
      }
      expected += '\n';
    }
  }
  std::ifstream in(dir.path() / "ts.csv");
  std::string line, body;
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#' && line.rfind("time[s]", 0) != 0) body += line + "\n";
  CHECK(body == expected);
  CHECK(expected.find(",-0,") != std::string::npos);
}
