#include "output/timeseries_reader.hpp"

#include <catch2/catch.hpp>
#include <cmath>

#include "support/scene_files.hpp"

using namespace yardsim;

TEST_CASE("a time series reads back with metadata, units and non-finite values") {
  testing::SceneDir dir;
  const auto f = dir.write("ts.csv", "# yardsim 0.1.0\n# scene a b.yaml\ntime[s],crane.hoist.tension[N],x[m/s^2]\n"
                                     "0,1.5e6,nan\n0.5,-2,inf\n");
  const auto ts = output::readTimeseries(f);
  CHECK(ts.meta.at("yardsim") == "0.1.0");
  CHECK(ts.meta.at("scene") == "a b.yaml");
  REQUIRE(ts.columns.size() == 3);
  CHECK(ts.columns[1].name == "crane.hoist.tension");
  CHECK(ts.columns[1].unit == "N");
  CHECK(ts.columns[2].unit == "m/s^2");
  CHECK(ts.columns[0].values == std::vector<double>{0.0, 0.5});
  CHECK(ts.columns[1].values == std::vector<double>{1.5e6, -2.0});
  CHECK(std::isnan(ts.columns[2].values[0]));
  CHECK(std::isinf(ts.columns[2].values[1]));
}

TEST_CASE("a bad cell is reported with file and line") {
  testing::SceneDir dir;
  const auto f = dir.write("ts.csv", "time[s],x[m]\n0,1\n0.1,abc\n");
  CHECK_THROWS_WITH(output::readTimeseries(f), Catch::Contains("ts.csv:3: expected a number, got 'abc'"));
  const auto g = dir.write("short.csv", "time[s],x[m]\n0\n");
  CHECK_THROWS_WITH(output::readTimeseries(g), Catch::Contains("short.csv:2: expected 2 cells"));
}
