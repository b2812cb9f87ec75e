#include "output/report_events.hpp"

#include <fstream>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "devs/trace_format.hpp"

namespace yardsim::output {

bool parseEventValue(const std::string& value, ReportEvent& out) {
  // (ELEMENT WHAT VALUE ...) => the three words, then " for ACTOR" and " (DETAIL)" if present
  std::istringstream in(value);
  std::string number;
  if (!(in >> out.element >> out.what >> number)) return false;
  try {
    std::size_t used = 0;
    out.value = std::stod(number, &used);
    if (used != number.size()) return false;
  } catch (const std::exception&) {
    return false;
  }
  const auto open = value.find(" (");
  out.detail = open != std::string::npos && value.back() == ')'
                   ? value.substr(open + 2, value.size() - open - 3)
                   : std::string();
  return true;
}

std::vector<ReportEvent> reportEvents(const std::filesystem::path& traceJsonl, std::size_t limit) {
  std::vector<ReportEvent> out;
  std::ifstream in(traceJsonl);
  for (std::string line; out.size() < limit && std::getline(in, line);) {
    if (line.find("\"port\":\"event\"") == std::string::npos ||
        line.find("\"kind\":\"out\"") == std::string::npos)
      continue;
    const YAML::Node r = YAML::Load(line);
    if (!r["value"] || !r["value"].IsScalar()) continue;
    ReportEvent e;
    if (!parseEventValue(r["value"].as<std::string>(), e)) continue;
    e.t = r["t"].as<double>();
    e.model = r["model"].as<std::string>();
    out.push_back(std::move(e));
  }
  return out;
}

void appendEventsJson(std::string& out, const std::vector<ReportEvent>& events) {
  out += "[";
  for (std::size_t i = 0; i < events.size(); ++i) {
    const ReportEvent& e = events[i];
    out += i ? ",{\"t\":" : "{\"t\":";
    devs::appendJsonNumber(out, e.t);
    devs::appendJsonString(out += ",\"model\":", e.model);
    devs::appendJsonString(out += ",\"element\":", e.element);
    devs::appendJsonString(out += ",\"what\":", e.what);
    devs::appendJsonNumber(out += ",\"value\":", e.value);
    devs::appendJsonString(out += ",\"detail\":", e.detail);
    out += "}";
  }
  out += "]";
}

}  // namespace yardsim::output
