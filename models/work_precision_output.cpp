#include "models/work_precision_output.hpp"

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "models/svg_plot.hpp"
#include "models/timeseries_writer.hpp"

namespace yardsim::models {
namespace {

void writeFile(const std::filesystem::path& p, const std::string& text) {
  std::ofstream out(p);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + p.string());
}

// (rows) => method labels in order of first appearance
std::vector<std::string> methods(const WpResult& r) {
  std::vector<std::string> out;
  for (const auto& row : r.rows)
    if (std::find(out.begin(), out.end(), row.run.label) == out.end()) out.push_back(row.run.label);
  return out;
}

}  // namespace

std::string wpCsv(const WpResult& r) {
  std::string s = std::string(kWpColumns) + "\n";
  auto num = [&](double v) {
    s += ',';
    appendCsvNumber(s, v);
  };
  for (const auto& row : r.rows) {
    const WpSeries& x = row.series;
    s += r.scene + "," + row.run.label + "," + row.run.param();
    num(row.omegaDt);
    for (std::uint64_t c : {x.steps, x.fEvals, x.jacEvals, x.newtonIts, x.errFails}) s += "," + std::to_string(c);
    for (double v : {row.error.final, row.error.rms, row.error.max, x.gMax, row.wallMedian}) num(v);
    s += "," + row.status + "\n";
  }
  return s;
}

std::string wpSummary(const WpResult& r, const WpSpec& spec) {
  std::ostringstream s;
  s.precision(3);
  s << "Scene `" << r.scene << "`: omega_max = " << r.omegaMax << " rad/s; error channels";
  for (const auto& c : spec.channels) s << " `" << c << "`";
  s << "; reference " << spec.reference.label << " " << spec.reference.param();
  if (spec.check.method.empty())
    s << " (published, not checked by a second run).\n\n";
  else
    s << ", checked by " << spec.check.label << " " << spec.check.param() << ": E_rms " << r.referenceCheck.rms
      << " m, E_max " << r.referenceCheck.max << " m (errors below that are measured against the reference alone).\n\n";
  s << "| method | time to E_rms <= 1e-3 m | time to E_rms <= 1e-6 m | blow-ups |\n|---|---|---|---|\n";
  for (const auto& m : methods(r)) {
    // (runs of this method) => the cheapest reaching each tolerance, and the ones that blew up
    double best3 = HUGE_VAL, best6 = HUGE_VAL;
    std::string p3, p6, blown;
    for (const auto& row : r.rows) {
      if (row.run.label != m) continue;
      if (row.status != "ok") {
        blown += (blown.empty() ? "" : ", ") + row.run.param();
        continue;
      }
      if (row.error.rms <= 1e-3 && row.wallMedian < best3) best3 = row.wallMedian, p3 = row.run.param();
      if (row.error.rms <= 1e-6 && row.wallMedian < best6) best6 = row.wallMedian, p6 = row.run.param();
    }
    auto cell = [](double t, const std::string& p) {
      std::ostringstream c;
      c.precision(3);
      if (std::isinf(t)) c << "not reached";
      else c << t << " s (" << p << ")";
      return c.str();
    };
    s << "| " << m << " | " << cell(best3, p3) << " | " << cell(best6, p6) << " | "
      << (blown.empty() ? "none" : blown) << " |\n";
  }
  return s.str();
}

void writeWp(const WpResult& r, const WpSpec& spec, const std::filesystem::path& outdir) {
  std::filesystem::create_directories(outdir);
  writeFile(outdir / "wp.csv", wpCsv(r));
  writeFile(outdir / "summary.md", wpSummary(r, spec));
  // (rows per method) => two panels: error against wall time, and against ABA evaluations
  PlotPanel byTime{r.scene + ": E_rms against wall time", "wall time (median), s", "E_rms, m", {}};
  PlotPanel byEvals{r.scene + ": E_rms against ABA evaluations", "right-hand-side (ABA) evaluations",
                    "E_rms, m", {}};
  for (const auto& m : methods(r)) {
    PlotSeries t{m, {}}, f{m, {}};
    for (const auto& row : r.rows)
      if (row.run.label == m && row.status == "ok") {
        t.points.emplace_back(row.wallMedian, row.error.rms);
        f.points.emplace_back(static_cast<double>(row.series.fEvals), row.error.rms);
      }
    byTime.series.push_back(t);
    byEvals.series.push_back(f);
  }
  writeFile(outdir / "wp.svg", logLogSvg({byTime, byEvals}));
}

}  // namespace yardsim::models
