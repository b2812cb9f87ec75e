// The sweep page's data: every table field, NaN as null, limits and the operability pair.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <sstream>

#include "output/sweep_page.hpp"
#include "support/scene_files.hpp"

using namespace yardsim::output;

TEST_CASE("The sweep page carries the case table, limits and operability pair as JSON") {
  SweepPage p;
  p.title = "yardsim sweep: s.yaml";
  p.facts = {{"cases", "2"}};
  p.params = {"speed", "mass"};
  p.collect = {"max(x.q)"};
  p.limits = {{"max(x.q)", 0.5, true}};
  p.operability = {"speed", "mass"};
  p.rows = {{0, {4, 0.5}, "ok", "", 0.25, {0.42}, true, "cases/000000/report.html"},
            {1, {6, 0.5}, "failed", "NaN \"here\"", 0.5, {std::nan("")}, false, ""}};
  const std::string j = sweepJson(p);
  CHECK_THAT(j, Catch::StartsWith("{\"kind\":\"sweep\",\"title\":\"yardsim sweep: s.yaml\""));
  CHECK_THAT(j, Catch::Contains("\"params\":[\"speed\",\"mass\"],\"collect\":[\"max(x.q)\"],"
                                "\"operability\":[\"speed\",\"mass\"]"));
  CHECK_THAT(
      j, Catch::Contains("\"limits\":[{\"collect\":\"max(x.q)\",\"bound\":0.5,\"upper\":true}]"));
  CHECK_THAT(j, Catch::Contains(
                    "{\"id\":0,\"values\":[4,0.5],\"status\":\"ok\",\"message\":\"\",\"wall\":0.25,"
                    "\"collected\":[0.41999999999999998],\"pass\":true,\"link\":\"cases/000000/"
                    "report.html\"}"));
  CHECK_THAT(j, Catch::Contains("\"message\":\"NaN \\\"here\\\"\""));
  CHECK_THAT(j, Catch::Contains("\"collected\":[null],\"pass\":false"));

  yardsim::testing::SceneDir dir;
  writeSweepPage(dir.path() / "sweep.html", p);
  std::ifstream is(dir.path() / "sweep.html");
  std::stringstream s;
  s << is.rdbuf();
  CHECK_THAT(s.str(), Catch::Contains("<script type=\"application/json\" id=\"yardsim-data\">"));
  CHECK_THAT(s.str(), Catch::Contains("\"kind\":\"sweep\""));
}
