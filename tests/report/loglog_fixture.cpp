// Writes a log-log page like `yardsim wp`'s wp.html: error against wall time and against ABA
// evaluations for two methods of order 4 and 2 (e = C h^p, work proportional to 1/h), with one
// run that reached zero error (not drawable on log axes).
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "output/loglog_page.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: report_loglog_fixture PAGE.html\n");
    return 1;
  }
  using namespace yardsim::output;
  LogLogPage page{"work-precision: fixture", {{"scene", "fixture"}, {"reference", "rk4, dt = 1e-5 s"}}, {}, {}};
  LogLogPlot wall{"error against wall time", "wall time [s]", "E_rms [m]", {}};
  LogLogPlot evals{"error against ABA evaluations", "ABA evaluations", "E_rms [m]", {}};
  for (auto [label, order, stages] : {std::tuple{"rk4", 4, 4}, {"semi_implicit_euler", 2, 1}}) {
    LogLogCurve w{label, {}, {}}, e{label, {}, {}};
    for (double h = 0.1; h > 1e-3; h /= 2) {
      const double err = 1e-1 * std::pow(h / 0.1, order);
      w.x.push_back(1e-4 * stages / h), w.y.push_back(err);
      e.x.push_back(std::round(10.0 * stages / h)), e.y.push_back(err);
    }
    wall.curves.push_back(w);
    evals.curves.push_back(e);
  }
  wall.curves[0].x.push_back(1.0), wall.curves[0].y.push_back(0.0);  // exact: not on log axes
  page.plots = {wall, evals};
  std::filesystem::create_directories(std::filesystem::path(argv[1]).parent_path());
  writeLogLogPage(argv[1], page);
}
