#include "studies/work_precision_output.hpp"

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "output/loglog_page.hpp"
#include "run/timeseries_writer.hpp"

namespace yardsim::studies {

using output::LogLogCurve;
using output::LogLogPage;
using output::LogLogPlot;
using output::writeLogLogPage;
using run::appendCsvNumber;
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

LogLogPage wpPage(const WpResult& r, const WpSpec& spec) {
  std::ostringstream omega;
  omega.precision(3);
  omega << r.omegaMax << " rad/s";
  std::string channels;
  for (const auto& c : spec.channels) channels += (channels.empty() ? "" : ", ") + c;
  LogLogPage page{"work-precision: " + r.scene,
                  {{"scene", r.scene}, {"omega_max", omega.str()}, {"error channels", channels},
                   {"reference", spec.reference.label + " " + spec.reference.param()},
                   {"checked by", spec.check.label + " " + spec.check.param()}},
                  {},
                  {}};
  // (rows per method) => two plots: error against wall time, and against ABA evaluations
  LogLogPlot byTime{"E_rms against wall time", "wall time (median) [s]", "E_rms [m]", {}};
  LogLogPlot byEvals{"E_rms against ABA evaluations", "right-hand-side (ABA) evaluations", "E_rms [m]", {}};
  std::size_t blown = 0;
  for (const auto& m : methods(r)) {
    LogLogCurve t{m, {}, {}}, f{m, {}, {}};
    for (const auto& row : r.rows) {
      if (row.run.label != m) continue;
      if (row.status != "ok") {
        ++blown;
        continue;
      }
      t.x.push_back(row.wallMedian), t.y.push_back(row.error.rms);
      f.x.push_back(static_cast<double>(row.series.fEvals)), f.y.push_back(row.error.rms);
    }
    byTime.curves.push_back(t);
    byEvals.curves.push_back(f);
  }
  page.plots = {byTime, byEvals};
  if (blown) page.notes.push_back(std::to_string(blown) + " run(s) blew up and are not drawn (wp.csv, summary.md)");
  return page;
}

void writeWp(const WpResult& r, const WpSpec& spec, const std::filesystem::path& outdir) {
  std::filesystem::create_directories(outdir);
  writeFile(outdir / "wp.csv", wpCsv(r));
  writeFile(outdir / "summary.md", wpSummary(r, spec));
  writeLogLogPage(outdir / "wp.html", wpPage(r, spec));
}

}  // namespace yardsim::studies
