#pragma once
// A page of log-log plots drawn by the report bundle (wp.html of `yardsim wp`: error against
// wall time and against ABA evaluations, one curve per method). Points with a non-positive
// coordinate cannot be drawn on log axes and are left out by the page (and counted in a note).
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace yardsim::output {

struct LogLogCurve {
  std::string label;           // e.g. "rk4"
  std::vector<double> x, y;    // one point per run
};

struct LogLogPlot {
  std::string title, xLabel, yLabel;  // labels with units: "wall time [s]"
  std::vector<LogLogCurve> curves;
};

struct LogLogPage {
  std::string title;                                      // h1 and <title>
  std::vector<std::pair<std::string, std::string>> facts; // header table rows
  std::vector<LogLogPlot> plots;
  std::vector<std::string> notes;
};

// (page) => the data JSON the bundle reads (kind "loglog"), arrays as base64 float32
std::string logLogJson(const LogLogPage& page);
// (file, page) => the HTML page written
void writeLogLogPage(const std::filesystem::path& file, const LogLogPage& page);

}  // namespace yardsim::output
