#pragma once
// A small log-log line plot as SVG (for `yardsim wp`; a later report replaces it): one or more
// panels side by side, each with decade grid lines, labelled axes and one polyline with
// markers per series, and a shared legend.
#include <string>
#include <utility>
#include <vector>

namespace yardsim::models {

struct PlotSeries {
  std::string name;
  std::vector<std::pair<double, double>> points;  // (x, y); non-positive or non-finite ones skipped
};

struct PlotPanel {
  std::string title, xLabel, yLabel;
  std::vector<PlotSeries> series;
};

// (panels) => a complete SVG document
std::string logLogSvg(const std::vector<PlotPanel>& panels);

}  // namespace yardsim::models
