// What `yardsim wp` writes: the CSV columns exactly as the issue names them, one row per run;
// the summary picks the cheapest run reaching each tolerance and lists the blow-ups; the plot
// has one line per method in each panel.
#include "models/work_precision_output.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <sstream>

#include "support/scene_files.hpp"

using namespace yardsim;

namespace {
models::WpRow row(const std::string& method, double dt, double rms, double wall, bool ok = true) {
  models::WpRow r;
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
std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}
}  // namespace

TEST_CASE("wp.csv, summary.md and wp.svg") {
  models::WpResult r;
  r.scene = "s";
  r.omegaMax = 100;
  r.rows = {row("rk4", 0.1, HUGE_VAL, 0.001, false), row("rk4", 0.05, 2e-3, 0.002), row("rk4", 0.025, 5e-4, 0.004),
            row("rk4", 0.0125, 3e-5, 0.008), row("euler", 0.01, 0.5e-3, 0.003)};
  models::WpSpec spec;
  spec.channels = {"block.z"};
  testing::SceneDir dir;
  models::writeWp(r, spec, dir.path());
  std::ifstream in(dir.path() / "wp.csv");
  std::string header;
  std::getline(in, header);
  CHECK(header ==
        "scene,method,param,omega_dt,steps,f_evals,jac_evals,newton_its,err_fails,E_final,E_rms,E_max,g_max,"
        "wall_median_s,status");
  std::size_t rows = 0;
  for (std::string line; std::getline(in, line);) rows += !line.empty();
  CHECK(rows == 5);
  const std::string text = models::wpCsv(r);
  CHECK_THAT(text, Catch::Contains("s,rk4,dt=0.05,5,20,80,0,0,0,0.002,0.002,0.004,0,0.002,ok"));
  CHECK_THAT(text, Catch::Contains(",blow-up\n"));
  const std::string summary = models::wpSummary(r, spec);
  INFO(summary);
  CHECK_THAT(summary, Catch::Contains("| rk4 | 0.004 s (dt=0.025) | not reached | dt=0.1 |"));
  CHECK_THAT(summary, Catch::Contains("| euler | 0.003 s (dt=0.01) | not reached | none |"));
  std::ifstream svgIn(dir.path() / "wp.svg");
  std::stringstream svg;
  svg << svgIn.rdbuf();
  CHECK(svg.str().rfind("<svg", 0) == 0);
  CHECK(count(svg.str(), "<polyline") == 4);  // two methods in two panels
  CHECK(count(svg.str(), "<circle") == 2 * 4);  // the blow-up is not plotted
}
