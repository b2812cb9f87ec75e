#include "output/report_writer.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

#include <yaml-cpp/yaml.h>

#include "devs/trace_format.hpp"
#include "models/channels.hpp"
#include "output/base64.hpp"
#include "output/html_page.hpp"
#include "output/report_events.hpp"

namespace yardsim::output {

using models::globMatch;
namespace {

using devs::appendJsonNumber;
using devs::appendJsonString;
namespace fs = std::filesystem;

std::string readFile(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read '" + file.string() + "'");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

std::vector<RopePeak> ropePeaks(const Timeseries& ts,
                                const std::vector<std::pair<std::string, double>>& staticLevels) {
  std::vector<RopePeak> out;
  const std::string suffix = ".tension";
  for (std::size_t c = 1; c < ts.columns.size(); ++c) {
    const auto& col = ts.columns[c];
    if (col.name.size() < suffix.size() ||
        col.name.compare(col.name.size() - suffix.size(), suffix.size(), suffix) != 0)
      continue;
    // (tension samples) => the largest finite one and when
    RopePeak p{col.name, -std::numeric_limits<double>::infinity(), 0.0, std::nullopt};
    for (std::size_t i = 0; i < col.values.size(); ++i)
      if (std::isfinite(col.values[i]) && col.values[i] > p.peak) {
        p.peak = col.values[i];
        p.time = ts.columns[0].values[i];
      }
    if (!std::isfinite(p.peak)) p.peak = 0.0;
    // (the rope's running maximum over every step, when recorded) => the peak between samples too,
    // dated by the first sample that holds it
    const std::string running = col.name.substr(0, col.name.size() - suffix.size()) + ".peak_tension";
    for (const auto& other : ts.columns)
      if (other.name == running && !other.values.empty() && std::isfinite(other.values.back()) &&
          other.values.back() > p.peak) {
        p.peak = other.values.back();
        for (std::size_t i = 0; i < other.values.size(); ++i)
          if (other.values[i] >= p.peak) {
            p.time = ts.columns[0].values[i];
            break;
          }
      }
    for (const auto& [name, value] : staticLevels)
      if (name == col.name) p.staticValue = value;
    out.push_back(p);
  }
  return out;
}

std::vector<ActorSpan> actorSpans(const fs::path& traceJsonl, std::vector<ActorSpan> actors) {
  std::ifstream in(traceJsonl);
  std::string line;
  while (std::getline(in, line)) {
    // (an actor's started / finished output) => its span
    const bool started = line.find("\"port\":\"started\"") != std::string::npos;
    if (!started && line.find("\"port\":\"finished\"") == std::string::npos) continue;
    if (line.find("\"kind\":\"out\"") == std::string::npos) continue;
    const YAML::Node r = YAML::Load(line);
    const auto model = r["model"].as<std::string>();
    const double t = r["t"].as<double>();
    auto it = std::find_if(actors.begin(), actors.end(), [&](const ActorSpan& a) { return a.path == model; });
    if (it == actors.end()) it = actors.insert(actors.end(), ActorSpan{model, "actor", -1.0, -1.0});
    if (started && it->start < 0) it->start = t;
    if (!started) it->end = t;
  }
  return actors;
}

void writeReport(const fs::path& outdir) {
  const fs::path csv = outdir / "timeseries.csv";
  if (!fs::exists(csv))
    throw std::runtime_error("'" + csv.string() + "' not found: is '" + outdir.string() +
                             "' the output folder of a `yardsim run` of a scene with a record: block?");
  const Timeseries ts = readTimeseries(csv);
  std::vector<std::string> notes;
  // (run.json) => header facts, plots and static levels, actors
  std::string runJson = "null";
  std::vector<std::string> plotGlobs;
  std::vector<std::pair<std::string, double>> staticLevels;
  std::vector<ActorSpan> actors;
  if (fs::exists(outdir / "run.json")) {
    runJson = readFile(outdir / "run.json");
    const YAML::Node run = YAML::Load(runJson);
    for (const auto& g : run["report"]["plots"]) plotGlobs.push_back(g.as<std::string>());
    for (const auto& s : run["report"]["static"])
      staticLevels.emplace_back(s.first.as<std::string>(), s.second.as<double>());
    for (const auto& a : run["actors"])
      actors.push_back({a["path"].as<std::string>(), a["kind"].as<std::string>(), -1.0, -1.0});
  } else {
    notes.push_back("no run.json: header facts, static levels and actor kinds are unknown");
  }
  std::vector<ReportEvent> events;
  if (fs::exists(outdir / "trace.jsonl")) {
    actors = actorSpans(outdir / "trace.jsonl", std::move(actors));
    events = reportEvents(outdir / "trace.jsonl");
  } else if (!actors.empty())
    notes.push_back(
        "no trace.jsonl: the actor timeline has no bars (run with --trace jsonl or --report)");

  std::string d = "{\"kind\":\"run\",\"run\":" + runJson + ",\"meta\":{";
  bool first = true;
  for (const auto& [k, v] : ts.meta) {
    appendJsonString(d += first ? "" : ",", k);
    appendJsonString(d += ":", v);
    first = false;
  }
  // (columns) => time and series as base64 float32, the plotted ones by glob
  d += "},\"time\":";
  appendFloat32Json(d, ts.columns[0].values);
  d += ",\"series\":[";
  std::vector<std::size_t> plotted;
  for (std::size_t c = 1; c < ts.columns.size(); ++c) {
    const auto& col = ts.columns[c];
    d += c > 1 ? ",{\"name\":" : "{\"name\":";
    appendJsonString(d, col.name);
    appendJsonString(d += ",\"unit\":", col.unit);
    d += ",\"data\":";
    appendFloat32Json(d, col.values);
    d += "}";
    if (plotGlobs.empty() ||
        std::any_of(plotGlobs.begin(), plotGlobs.end(), [&](const auto& g) { return globMatch(g, col.name); }))
      plotted.push_back(c - 1);
  }
  for (const auto& g : plotGlobs)
    if (std::none_of(ts.columns.begin() + 1, ts.columns.end(), [&](const auto& c) { return globMatch(g, c.name); }))
      notes.push_back("report.plots: '" + g + "' matches no recorded channel (record.channels must record it)");
  d += "],\"plots\":[";
  for (std::size_t i = 0; i < plotted.size(); ++i) d += (i ? "," : "") + std::to_string(plotted[i]);
  d += "],\"static\":{";
  for (std::size_t i = 0; i < staticLevels.size(); ++i) {
    appendJsonString(d += i ? "," : "", staticLevels[i].first);
    appendJsonNumber(d += ":", staticLevels[i].second);
  }
  d += "},\"peaks\":[";
  const auto peaks = ropePeaks(ts, staticLevels);
  for (std::size_t i = 0; i < peaks.size(); ++i) {
    appendJsonString(d += i ? ",{\"channel\":" : "{\"channel\":", peaks[i].channel);
    appendJsonNumber(d += ",\"peak\":", peaks[i].peak);
    appendJsonNumber(d += ",\"time\":", peaks[i].time);
    d += ",\"static\":";
    if (peaks[i].staticValue) appendJsonNumber(d, *peaks[i].staticValue);
    else d += "null";
    d += "}";
  }
  d += "],\"actors\":[";
  for (std::size_t i = 0; i < actors.size(); ++i) {
    appendJsonString(d += i ? ",{\"path\":" : "{\"path\":", actors[i].path);
    appendJsonString(d += ",\"kind\":", actors[i].kind);
    appendJsonNumber(d += ",\"start\":", actors[i].start);
    appendJsonNumber(d += ",\"end\":", actors[i].end);
    d += "}";
  }
  d += "],\"events\":";
  appendEventsJson(d, events);
  // (replay.glb) => its bytes
  d += ",\"glb\":";
  if (fs::exists(outdir / "replay.glb")) {
    const std::string glb = readFile(outdir / "replay.glb");
    d += '"';
    appendBase64(d, glb.data(), glb.size());
    d += '"';
  } else {
    d += "null";
  }
  d += ",\"notes\":[";
  for (std::size_t i = 0; i < notes.size(); ++i) appendJsonString(d += i ? "," : "", notes[i]);
  d += "]}";

  std::string title = "yardsim report";
  if (runJson != "null") title += ": " + YAML::Load(runJson)["scene"].as<std::string>();
  writeTextFile(outdir / "report.html", htmlPage(title, std::move(d)));
}

}  // namespace yardsim::output
