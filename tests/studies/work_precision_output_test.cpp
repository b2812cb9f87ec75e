// What `yardsim wp` writes: the CSV columns exactly as the issue names them, one row per run;
// the summary picks the cheapest run reaching each tolerance and lists the blow-ups; wp.html
// has one curve per method in each plot, without the blow-ups.
#include "studies/work_precision_output.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <sstream>

#include "support/scene_files.hpp"

using namespace yardsim;

namespace {
studies::WpRow row(const std::string& method, double dt, double rms, double wall, bool ok = true) {
  studies::WpRow r;
  r.run.label = r.run.method = method;
  r.run.dt = dt;
  r.omegaDt = 100 * dt;
  r.error = {rms, rms, 2 * rms};
  r.wallMedian = wall;
  r.status = ok ? "ok" : "blow-up";
  r.series.steps = static_cast<std::uint64_t>(1.0 / dt);
  r.series.fEvals = 4 * r.series.steps;
  return r;
}
}  // namespace

TEST_CASE("wp.csv, summary.md and wp.html") {
  studies::WpResult r;
  r.scene = "s";
  r.omegaMax = 100;
  r.rows = {row("rk4", 0.1, HUGE_VAL, 0.001, false), row("rk4", 0.05, 2e-3, 0.002), row("rk4", 0.025, 5e-4, 0.004),
            row("rk4", 0.0125, 3e-5, 0.008), row("euler", 0.01, 0.5e-3, 0.003)};
  studies::WpSpec spec;
  spec.channels = {"block.z"};
  testing::SceneDir dir;
  studies::writeWp(r, spec, dir.path());
  std::ifstream in(dir.path() / "wp.csv");
  std::string header;
  std::getline(in, header);
  CHECK(header ==
        "scene,method,param,omega_dt,steps,f_evals,jac_evals,newton_its,err_fails,E_final,E_rms,E_max,g_max,"
        "wall_median_s,status");
  std::size_t rows = 0;
  for (std::string line; std::getline(in, line);) rows += !line.empty();
  CHECK(rows == 5);
  const std::string text = studies::wpCsv(r);
  CHECK_THAT(text, Catch::Contains("s,rk4,dt=0.05,5,20,80,0,0,0,0.002,0.002,0.004,0,0.002,ok"));
  CHECK_THAT(text, Catch::Contains(",blow-up\n"));
  const std::string summary = studies::wpSummary(r, spec);
  INFO(summary);
  CHECK_THAT(summary, Catch::Contains("| rk4 | 0.004 s (dt=0.025) | not reached | dt=0.1 |"));
  CHECK_THAT(summary, Catch::Contains("| euler | 0.003 s (dt=0.01) | not reached | none |"));
  // (page) => two plots, a curve per method, the blow-up left out and noted
  const output::LogLogPage page = studies::wpPage(r, spec);
  REQUIRE(page.plots.size() == 2);
  for (const auto& plot : page.plots) {
    REQUIRE(plot.curves.size() == 2);
    CHECK(plot.curves[0].label == "rk4");
    CHECK(plot.curves[0].x.size() == 3);
    CHECK(plot.curves[1].x.size() == 1);
  }
  CHECK(page.plots[0].curves[0].x == std::vector<double>{0.002, 0.004, 0.008});
  CHECK(page.plots[1].curves[0].x == std::vector<double>{80, 160, 320});
  CHECK(page.plots[1].curves[0].y == std::vector<double>{2e-3, 5e-4, 3e-5});
  CHECK_THAT(page.notes.at(0), Catch::Contains("1 run(s) blew up"));
  std::ifstream htmlIn(dir.path() / "wp.html");
  std::stringstream html;
  html << htmlIn.rdbuf();
  CHECK(html.str().rfind("<!doctype html>", 0) == 0);
  CHECK_THAT(html.str(), Catch::Contains("\"kind\":\"loglog\""));
}
