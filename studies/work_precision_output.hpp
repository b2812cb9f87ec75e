#pragma once
// What `yardsim wp` writes (docs/numerics.md): OUTDIR/wp.csv (one row per run, the columns
// below), OUTDIR/wp.html (log-log: error against wall time and against ABA evaluations, drawn
// by the report bundle, docs/report.md) and
// OUTDIR/summary.md (per method, the time to reach E_rms <= 1e-3 m and <= 1e-6 m; the
// reference's own accuracy).
#include <filesystem>
#include <string>

#include "output/loglog_page.hpp"
#include "studies/work_precision.hpp"

namespace yardsim::studies {

using output::LogLogPage;

inline constexpr const char* kWpColumns =
    "scene,method,param,omega_dt,steps,f_evals,jac_evals,newton_its,err_fails,E_final,E_rms,E_max,"
    "g_max,wall_median_s,status";

// (result) => the CSV text: the header kWpColumns, then one row per run
std::string wpCsv(const WpResult& r);
// (result) => the summary as a Markdown table, one row per method
std::string wpSummary(const WpResult& r, const WpSpec& spec);
// (result, spec) => the page of wp.html: per method, E_rms against wall time and against ABA
// evaluations (runs that blew up left out, and counted in a note)
LogLogPage wpPage(const WpResult& r, const WpSpec& spec);
// (result, folder) => wp.csv, wp.html and summary.md written; throws std::runtime_error naming
// a file that cannot be written
void writeWp(const WpResult& r, const WpSpec& spec, const std::filesystem::path& outdir);

}  // namespace yardsim::studies
