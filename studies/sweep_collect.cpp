#include "studies/sweep_collect.hpp"

#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <yaml-cpp/yaml.h>

#include "output/hdf5_file.hpp"
#include "output/report_writer.hpp"
#include "output/sweep_page.hpp"
#include "output/timeseries_hdf5.hpp"
#include "output/timeseries_reader.hpp"
#include "run/timeseries_writer.hpp"
#include "scene/sha256.hpp"

namespace yardsim::studies {

namespace fs = std::filesystem;

namespace {

// (file) => its bytes
std::string bytesOf(const fs::path& file) {
  std::ifstream is(file, std::ios::binary);
  std::ostringstream s;
  s << is.rdbuf();
  return s.str();
}

// (value) => 17 significant digits, "nan" for NaN
std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// (text) => a CSV field, quoted when it holds a comma, quote or line break (line breaks as spaces)
std::string csvField(std::string s) {
  std::replace(s.begin(), s.end(), '\n', ' ');
  if (s.find_first_of(",\"") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

// (spec, records, OUT) => OUT/cases.csv
void writeCsv(const SweepSpec& spec, const std::vector<CaseRecord>& rs, const fs::path& out) {
  std::ofstream os(out / "cases.csv", std::ios::trunc);
  os << "id";
  for (const auto& p : spec.params) os << "," << csvField(p.name);
  os << ",status,wall_s,run_wall_s,t_end_s";
  for (const auto& c : spec.collect) os << "," << csvField(c.text);
  os << ",pass,rank,message\n";
  for (const auto& r : rs) {
    os << r.id;
    for (std::size_t k = 0; k < r.values.size(); ++k)
      os << "," << formatValue(r.values[k], spec.params[k].integer);
    os << "," << r.status << "," << num(r.wall) << "," << num(r.runWall) << "," << num(r.tEnd);
    for (double v : r.collected) os << "," << num(v);
    os << "," << (passes(spec, r) ? 1 : 0) << "," << r.rank << "," << csvField(r.message) << "\n";
  }
  if (!os) throw std::runtime_error("cannot write " + (out / "cases.csv").string());
}

// (spec, records, OUT) => OUT/sweep.h5: /table/... columns, /cases/<id>/ series when asked
void writeHdf5(const SweepSpec& spec, const std::vector<CaseRecord>& rs, const fs::path& out) {
  output::Hdf5File h(out / "sweep.h5.tmp");
  h.group("/table");
  h.attribute("/", "sweep", fs::absolute(spec.file).string());
  h.attribute("/", "scene", fs::absolute(spec.scene).string());
  h.attribute("/", "mode", spec.mode);
  h.attribute("/", "yardsim", run::kVersion);
  std::vector<std::int64_t> ids, ranks, pass;
  std::vector<std::string> status, message;
  std::vector<double> wall, runWall, tEnd;
  for (const auto& r : rs) {
    ids.push_back(static_cast<std::int64_t>(r.id));
    ranks.push_back(r.rank);
    pass.push_back(passes(spec, r) ? 1 : 0);
    status.push_back(r.status);
    message.push_back(r.message);
    wall.push_back(r.wall);
    runWall.push_back(r.runWall);
    tEnd.push_back(r.tEnd);
  }
  h.integers("/table/id", ids);
  h.strings("/table/status", status);
  h.strings("/table/message", message);
  h.doubles("/table/wall", wall);
  h.attribute("/table/wall", "unit", "s");
  h.doubles("/table/run_wall", runWall);
  h.attribute("/table/run_wall", "unit", "s");
  h.doubles("/table/t_end", tEnd);
  h.attribute("/table/t_end", "unit", "s");
  h.integers("/table/pass", pass);
  h.integers("/table/rank", ranks);
  h.group("/table/params");
  for (std::size_t k = 0; k < spec.params.size(); ++k) {
    std::vector<double> col;
    for (const auto& r : rs) col.push_back(r.values[k]);
    h.doubles("/table/params/" + spec.params[k].name, col);
  }
  h.group("/table/collected");
  for (std::size_t k = 0; k < spec.collect.size(); ++k) {
    std::vector<double> col;
    for (const auto& r : rs) col.push_back(r.collected[k]);
    const std::string path = "/table/collected/" + spec.collect[k].text;
    h.doubles(path, col);
    for (const auto& l : spec.limits)
      if (l.collect == spec.collect[k].text)
        h.attribute(path, "limit", (l.upper ? "<= " : ">= ") + num(l.bound));
  }
  if (spec.series)
    for (const auto& r : rs) {
      const fs::path csv = caseDir(out, r.id) / "timeseries.csv";
      if (!fs::exists(csv)) continue;
      output::writeTimeseriesGroup(h, "/cases/" + caseDir(out, r.id).filename().string(),
                                   output::readTimeseries(csv));
    }
}

// (spec, records) => the indices of up to 3 worst cases: largest use of the first limit (or of
// the first collected quantity), failures first
std::vector<std::size_t> worstCases(const SweepSpec& spec, const std::vector<CaseRecord>& rs) {
  std::vector<std::pair<double, std::size_t>> score;
  for (std::size_t i = 0; i < rs.size(); ++i) {
    if (rs[i].status == "missing") continue;
    double s = rs[i].status == "ok" ? 0.0 : 1e300;
    if (rs[i].status == "ok" && !spec.collect.empty()) {
      const std::string q = spec.limits.empty() ? spec.collect[0].text : spec.limits[0].collect;
      for (std::size_t k = 0; k < spec.collect.size(); ++k)
        if (spec.collect[k].text == q && std::isfinite(rs[i].collected[k]))
          s = spec.limits.empty() || spec.limits[0].upper ? rs[i].collected[k]
                                                          : -rs[i].collected[k];
    }
    score.push_back({s, i});
  }
  std::sort(score.begin(), score.end(),
            [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<std::size_t> worst;
  for (std::size_t i = 0; i < std::min<std::size_t>(3, score.size()); ++i)
    worst.push_back(score[i].second);
  return worst;
}

// (spec, records, counts, OUT) => OUT/sweep.html, with reports of the worst cases linked
void writePage(const SweepSpec& spec, const std::vector<CaseRecord>& rs, const SweepCounts& n,
               const fs::path& out) {
  output::SweepPage page;
  page.title = "yardsim sweep: " + spec.file.filename().string();
  double wall = 0.0;
  for (const auto& r : rs) wall += r.wall;
  page.facts = {{"sweep file", spec.file.string()},
                {"scene", spec.scene.string()},
                {"mode", spec.mode},
                {"cases", std::to_string(n.total) + " (" + std::to_string(n.ok) + " ok, " +
                              std::to_string(n.failed) + " not ok, " + std::to_string(n.missing) +
                              " missing)"},
                {"within the limits", std::to_string(n.passed)},
                {"case wall time, sum", num(wall) + " s"},
                {"yardsim", run::kVersion}};
  for (const auto& p : spec.params) page.params.push_back(p.name);
  for (const auto& c : spec.collect) page.collect.push_back(c.text);
  for (const auto& l : spec.limits) page.limits.push_back({l.collect, l.bound, l.upper});
  page.operability = spec.operability;
  const auto worst = worstCases(spec, rs);
  for (std::size_t i = 0; i < rs.size(); ++i) {
    const auto& r = rs[i];
    output::SweepRow row{static_cast<long long>(r.id),
                         r.values,
                         r.status,
                         r.message,
                         r.wall,
                         r.collected,
                         passes(spec, r),
                         ""};
    if (std::find(worst.begin(), worst.end(), i) != worst.end()) {
      try {  // (a worst case's outputs) => its report; a case that left too little has none
        output::writeReport(caseDir(out, r.id));
        row.link = (fs::path("cases") / caseDir(out, r.id).filename() / "report.html").string();
      } catch (const std::exception&) {
      }
    }
    page.rows.push_back(row);
  }
  output::writeSweepPage(out / "sweep.html", page);
}

}  // namespace

void writePlan(const SweepSpec& spec, const fs::path& out) {
  const std::string hash = scene::sha256Hex(bytesOf(spec.file));
  const fs::path file = out / "plan.yaml";
  if (fs::exists(file)) {
    const YAML::Node old = YAML::LoadFile(file.string());
    if (old["sha256"].as<std::string>("") != hash)
      throw std::runtime_error(out.string() + " holds the results of another sweep (" +
                               old["sweep"].as<std::string>("?") +
                               ", or an edited one); choose another -o");
    return;
  }
  fs::create_directories(out);
  // (array tasks starting at once) => each writes its own temporary file; the renames agree
  const std::string tmp = file.string() + "." + std::to_string(getpid()) + ".tmp";
  std::ofstream os(tmp, std::ios::trunc);
  os << "sweep: " << YAML::Node(fs::absolute(spec.file).string()) << "\nsha256: " << hash << "\n";
  os.close();
  fs::rename(tmp, file);
}

fs::path planSweepFile(const fs::path& out) {
  const fs::path file = out / "plan.yaml";
  if (!fs::exists(file))
    throw std::runtime_error(out.string() + " has no plan.yaml: not the folder of a sweep");
  return YAML::LoadFile(file.string())["sweep"].as<std::string>();
}

std::vector<CaseRecord> gatherRecords(const SweepSpec& spec, const std::vector<SweepCase>& cases,
                                      const fs::path& out) {
  std::vector<CaseRecord> rs;
  for (const auto& c : cases) {
    auto r = readCaseRecord(caseDir(out, c.id) / "case.yaml");
    if (!r || r->values != c.values || r->collected.size() != spec.collect.size()) {
      r = CaseRecord{};
      r->id = c.id;
      r->values = c.values;
      r->collected.assign(spec.collect.size(), std::nan(""));
    }
    rs.push_back(*r);
  }
  return rs;
}

bool passes(const SweepSpec& spec, const CaseRecord& r) {
  if (r.status != "ok") return false;
  for (const auto& l : spec.limits)
    for (std::size_t k = 0; k < spec.collect.size(); ++k)
      if (spec.collect[k].text == l.collect) {
        const double v = r.collected[k];
        if (!std::isfinite(v) || (l.upper ? v > l.bound : v < l.bound)) return false;
      }
  return true;
}

SweepCounts writeSweepResults(const SweepSpec& spec, const std::vector<CaseRecord>& rs,
                              const fs::path& out) {
  SweepCounts n;
  for (const auto& r : rs) {
    ++n.total;
    if (r.status == "ok")
      ++n.ok;
    else if (r.status == "missing")
      ++n.missing;
    else
      ++n.failed;
    if (passes(spec, r)) ++n.passed;
  }
  writeCsv(spec, rs, out);
  writeHdf5(spec, rs, out);
  fs::rename(out / "sweep.h5.tmp", out / "sweep.h5");
  writePage(spec, rs, n, out);
  return n;
}

}  // namespace yardsim::studies
