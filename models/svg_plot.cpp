#include "models/svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace yardsim::models {
namespace {

constexpr double kW = 460, kH = 340, kLeft = 70, kRight = 15, kTop = 35, kBottom = 50, kLegend = 22;
const char* const kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e",
                                "#8c564b", "#e377c2", "#17becf", "#7f7f7f", "#bcbd22"};

bool usable(const std::pair<double, double>& p) {
  return std::isfinite(p.first) && std::isfinite(p.second) && p.first > 0 && p.second > 0;
}

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else out += c;
  }
  return out;
}

}  // namespace

std::string logLogSvg(const std::vector<PlotPanel>& panels) {
  std::size_t nSeries = 0;
  for (const auto& p : panels) nSeries = std::max(nSeries, p.series.size());
  const double width = kW * static_cast<double>(panels.size());
  const double height = kH + kLegend * static_cast<double>((nSeries + 2) / 3);
  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
    << "\" font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  for (std::size_t pi = 0; pi < panels.size(); ++pi) {
    const PlotPanel& p = panels[pi];
    const double x0 = kW * static_cast<double>(pi);
    // (points) => decade bounds of both axes
    double lx0 = 1e300, lx1 = -1e300, ly0 = 1e300, ly1 = -1e300;
    for (const auto& ser : p.series)
      for (const auto& pt : ser.points)
        if (usable(pt)) {
          lx0 = std::min(lx0, std::log10(pt.first)), lx1 = std::max(lx1, std::log10(pt.first));
          ly0 = std::min(ly0, std::log10(pt.second)), ly1 = std::max(ly1, std::log10(pt.second));
        }
    if (lx0 > lx1) lx0 = 0, lx1 = 1, ly0 = 0, ly1 = 1;
    lx0 = std::floor(lx0), lx1 = std::max(std::ceil(lx1), lx0 + 1);
    ly0 = std::floor(ly0), ly1 = std::max(std::ceil(ly1), ly0 + 1);
    const double pw = kW - kLeft - kRight, ph = kH - kTop - kBottom;
    auto X = [&](double v) { return x0 + kLeft + (std::log10(v) - lx0) / (lx1 - lx0) * pw; };
    auto Y = [&](double v) { return kTop + (ly1 - std::log10(v)) / (ly1 - ly0) * ph; };
    s << "<text x=\"" << x0 + kW / 2 << "\" y=\"18\" text-anchor=\"middle\" font-size=\"13\">" << escape(p.title)
      << "</text>\n";
    s << "<rect x=\"" << x0 + kLeft << "\" y=\"" << kTop << "\" width=\"" << pw << "\" height=\"" << ph
      << "\" fill=\"none\" stroke=\"black\"/>\n";
    // (decades) => grid lines and tick labels
    for (double d = lx0; d <= lx1 + 1e-9; d += 1.0) {
      const double x = X(std::pow(10.0, d));
      s << "<line x1=\"" << x << "\" y1=\"" << kTop << "\" x2=\"" << x << "\" y2=\"" << kTop + ph
        << "\" stroke=\"#ddd\"/><text x=\"" << x << "\" y=\"" << kTop + ph + 15
        << "\" text-anchor=\"middle\">1e" << d << "</text>\n";
    }
    for (double d = ly0; d <= ly1 + 1e-9; d += 1.0) {
      const double y = Y(std::pow(10.0, d));
      s << "<line x1=\"" << x0 + kLeft << "\" y1=\"" << y << "\" x2=\"" << x0 + kLeft + pw << "\" y2=\"" << y
        << "\" stroke=\"#ddd\"/><text x=\"" << x0 + kLeft - 5 << "\" y=\"" << y + 4
        << "\" text-anchor=\"end\">1e" << d << "</text>\n";
    }
    s << "<text x=\"" << x0 + kLeft + pw / 2 << "\" y=\"" << kH - 12 << "\" text-anchor=\"middle\">"
      << escape(p.xLabel) << "</text>\n";
    s << "<text transform=\"translate(" << x0 + 16 << "," << kTop + ph / 2
      << ") rotate(-90)\" text-anchor=\"middle\">" << escape(p.yLabel) << "</text>\n";
    for (std::size_t si = 0; si < p.series.size(); ++si) {
      const char* colour = kColours[si % (sizeof(kColours) / sizeof(kColours[0]))];
      std::ostringstream line;
      for (const auto& pt : p.series[si].points)
        if (usable(pt)) {
          line << X(pt.first) << "," << Y(pt.second) << " ";
          s << "<circle cx=\"" << X(pt.first) << "\" cy=\"" << Y(pt.second) << "\" r=\"3\" fill=\"" << colour
            << "\"/>\n";
        }
      s << "<polyline points=\"" << line.str() << "\" fill=\"none\" stroke=\"" << colour << "\"/>\n";
    }
  }
  // (series names of the first panel) => legend
  if (!panels.empty())
    for (std::size_t si = 0; si < panels[0].series.size(); ++si) {
      const double lx = 20 + 200 * static_cast<double>(si % 3);
      const double ly = kH + kLegend * static_cast<double>(si / 3) + 8;
      s << "<rect x=\"" << lx << "\" y=\"" << ly - 8 << "\" width=\"14\" height=\"4\" fill=\""
        << kColours[si % (sizeof(kColours) / sizeof(kColours[0]))] << "\"/><text x=\"" << lx + 20 << "\" y=\""
        << ly << "\">" << escape(panels[0].series[si].name) << "</text>\n";
    }
  s << "</svg>\n";
  return s.str();
}

}  // namespace yardsim::models
