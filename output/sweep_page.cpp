#include "output/sweep_page.hpp"

#include <cmath>
#include <cstdio>

#include "devs/trace_format.hpp"
#include "output/html_page.hpp"

namespace yardsim::output {

using devs::appendJsonString;

namespace {
// (text, number) => appended as a JSON number, 17 digits; NaN and infinities as null
void appendNumber(std::string& d, double v) {
  if (!std::isfinite(v)) {
    d += "null";
    return;
  }
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  d += buf;
}
// (text, strings) => appended as a JSON array of strings
void appendStrings(std::string& d, const std::vector<std::string>& v) {
  d += "[";
  for (std::size_t i = 0; i < v.size(); ++i) appendJsonString(d += i ? "," : "", v[i]);
  d += "]";
}
// (text, numbers) => appended as a JSON array of numbers
void appendNumbers(std::string& d, const std::vector<double>& v) {
  d += "[";
  for (std::size_t i = 0; i < v.size(); ++i) appendNumber(d += i ? "," : "", v[i]);
  d += "]";
}
}  // namespace

std::string sweepJson(const SweepPage& page) {
  std::string d = "{\"kind\":\"sweep\",\"title\":";
  appendJsonString(d, page.title);
  d += ",\"facts\":[";
  for (std::size_t i = 0; i < page.facts.size(); ++i) {
    appendJsonString(d += i ? ",[" : "[", page.facts[i].first);
    appendJsonString(d += ",", page.facts[i].second);
    d += "]";
  }
  appendStrings(d += "],\"params\":", page.params);
  appendStrings(d += ",\"collect\":", page.collect);
  appendStrings(d += ",\"operability\":", page.operability);
  d += ",\"limits\":[";
  for (std::size_t i = 0; i < page.limits.size(); ++i) {
    appendJsonString(d += i ? ",{\"collect\":" : "{\"collect\":", page.limits[i].collect);
    appendNumber(d += ",\"bound\":", page.limits[i].bound);
    d += page.limits[i].upper ? ",\"upper\":true}" : ",\"upper\":false}";
  }
  d += "],\"rows\":[";
  for (std::size_t i = 0; i < page.rows.size(); ++i) {
    const SweepRow& r = page.rows[i];
    d += i ? ",{\"id\":" : "{\"id\":";
    d += std::to_string(r.id);
    appendNumbers(d += ",\"values\":", r.values);
    appendJsonString(d += ",\"status\":", r.status);
    appendJsonString(d += ",\"message\":", r.message);
    appendNumber(d += ",\"wall\":", r.wall);
    appendNumbers(d += ",\"collected\":", r.collected);
    d += r.pass ? ",\"pass\":true" : ",\"pass\":false";
    appendJsonString(d += ",\"link\":", r.link);
    d += "}";
  }
  return d + "]}";
}

void writeSweepPage(const std::filesystem::path& file, const SweepPage& page) {
  writeTextFile(file, htmlPage(page.title, sweepJson(page)));
}

}  // namespace yardsim::output
