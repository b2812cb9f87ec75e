#include "output/loglog_page.hpp"

#include <stdexcept>

#include "devs/trace_format.hpp"
#include "output/base64.hpp"
#include "output/html_page.hpp"

namespace yardsim::output {

using devs::appendJsonString;

std::string logLogJson(const LogLogPage& page) {
  std::string d = "{\"kind\":\"loglog\",\"title\":";
  appendJsonString(d, page.title);
  d += ",\"facts\":[";
  for (std::size_t i = 0; i < page.facts.size(); ++i) {
    appendJsonString(d += i ? ",[" : "[", page.facts[i].first);
    appendJsonString(d += ",", page.facts[i].second);
    d += "]";
  }
  d += "],\"plots\":[";
  for (std::size_t p = 0; p < page.plots.size(); ++p) {
    const LogLogPlot& plot = page.plots[p];
    appendJsonString(d += p ? ",{\"title\":" : "{\"title\":", plot.title);
    appendJsonString(d += ",\"x\":", plot.xLabel);
    appendJsonString(d += ",\"y\":", plot.yLabel);
    d += ",\"curves\":[";
    for (std::size_t c = 0; c < plot.curves.size(); ++c) {
      const LogLogCurve& curve = plot.curves[c];
      if (curve.x.size() != curve.y.size())
        throw std::invalid_argument("log-log curve '" + curve.label + "' has " + std::to_string(curve.x.size()) +
                                    " x and " + std::to_string(curve.y.size()) + " y values");
      appendJsonString(d += c ? ",{\"label\":" : "{\"label\":", curve.label);
      appendFloat32Json(d += ",\"xs\":", curve.x);
      appendFloat32Json(d += ",\"ys\":", curve.y);
      d += "}";
    }
    d += "]}";
  }
  d += "],\"notes\":[";
  for (std::size_t i = 0; i < page.notes.size(); ++i) appendJsonString(d += i ? "," : "", page.notes[i]);
  return d + "]}";
}

void writeLogLogPage(const std::filesystem::path& file, const LogLogPage& page) {
  writeTextFile(file, htmlPage(page.title, logLogJson(page)));
}

}  // namespace yardsim::output
