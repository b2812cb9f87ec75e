#include "studies/sweep_case.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "devs/coupled.hpp"
#include "devs/simulator.hpp"
#include "models/channels.hpp"
#include "output/timeseries_reader.hpp"
#include "run/runner.hpp"
#include "scene/assembler.hpp"
#include "scene/scene_loader.hpp"

namespace yardsim::studies {

namespace fs = std::filesystem;

namespace {

// (spec, case) => the root params it overrides, marked where the sweep file varies them
scene::ParamOverrides overridesOf(const SweepSpec& spec, const SweepCase& c) {
  scene::ParamOverrides o;
  for (std::size_t k = 0; k < spec.params.size(); ++k) {
    const SweepParam& p = spec.params[k];
    if (p.sceneSeed) continue;
    o[p.name] = {YAML::Node(formatValue(c.values[k], p.integer)), p.where, "sweep.vary." + p.name};
  }
  return o;
}

// (values, op) => the op over them (NaN when empty)
double reduce(const std::vector<const std::vector<double>*>& columns, const std::string& op) {
  double acc = op == "min" ? std::numeric_limits<double>::infinity()
                           : -std::numeric_limits<double>::infinity();
  double sum = 0.0;
  std::size_t n = 0;
  for (const auto* col : columns) {
    if (col->empty()) continue;
    if (op == "final") {
      acc = std::max(acc, col->back());
      ++n;
      continue;
    }
    for (double v : *col) {
      if (op == "max")
        acc = std::max(acc, v);
      else if (op == "min")
        acc = std::min(acc, v);
      else if (op == "absmax")
        acc = std::max(acc, std::abs(v));
      sum += v;
      ++n;
    }
  }
  if (n == 0) return std::nan("");
  return op == "mean" ? sum / static_cast<double>(n) : acc;
}

}  // namespace

fs::path caseDir(const fs::path& out, std::size_t id) {
  char name[32];
  std::snprintf(name, sizeof name, "%06zu", id);
  return out / "cases" / name;
}

models::Diagnostics checkCase(const SweepSpec& spec, const SweepCase& c) {
  auto loaded = scene::loadScene(spec.scene, overridesOf(spec, c));
  if (!loaded.scene) return std::move(loaded.diagnostics);
  models::Diagnostics& d = loaded.diagnostics;
  std::vector<std::string> recorded;
  try {  // (the scene's models) => the channels it records; a failing assembly is the case's own
         // result
    auto root = scene::assemble(*loaded.scene);
    if (loaded.scene->record.interval > 0)
      for (const auto& ch :
           models::selectChannels(models::collectChannels(*root), loaded.scene->record.channels))
        recorded.push_back(ch.name);
  } catch (const std::exception&) {
    return std::move(d);
  }
  for (const auto& col : spec.collect) {
    const bool any = std::any_of(recorded.begin(), recorded.end(), [&](const std::string& n) {
      return models::globMatch(col.glob, n);
    });
    if (!any)
      d.error(col.where, "sweep.collect." + col.text,
              "no recorded channel of " + spec.scene.string() + " matches '" + col.glob +
                  "' (the scene's `record.channels` choose what is recorded; yardsim list-channels "
                  "lists them)",
              models::didYouMean(col.glob, recorded));
  }
  return std::move(d);
}

std::vector<double> collectScalars(const SweepSpec& spec, const fs::path& timeseriesCsv) {
  std::vector<double> out(spec.collect.size(), std::nan(""));
  if (spec.collect.empty() || !fs::exists(timeseriesCsv)) return out;
  const output::Timeseries ts = output::readTimeseries(timeseriesCsv);
  for (std::size_t i = 0; i < spec.collect.size(); ++i) {
    std::vector<const std::vector<double>*> cols;
    for (std::size_t k = 1; k < ts.columns.size(); ++k)
      if (models::globMatch(spec.collect[i].glob, ts.columns[k].name))
        cols.push_back(&ts.columns[k].values);
    out[i] = reduce(cols, spec.collect[i].op);
  }
  return out;
}

CaseRecord runCase(const SweepSpec& spec, const SweepCase& c, const fs::path& out, int rank) {
  const auto start = std::chrono::steady_clock::now();
  CaseRecord r;
  r.id = c.id;
  r.values = c.values;
  r.rank = rank;
  r.collected.assign(spec.collect.size(), std::nan(""));
  const fs::path dir = caseDir(out, c.id);
  try {
    fs::create_directories(dir);
    auto loaded = scene::loadScene(spec.scene, overridesOf(spec, c));
    if (!loaded.scene) {
      r.status = "refused";
      r.message = loaded.diagnostics.report();
    } else {
      scene::Scene& sc = *loaded.scene;
      for (std::size_t k = 0; k < spec.params.size(); ++k)
        if (spec.params[k].sceneSeed) sc.seed = std::llround(c.values[k]);
      run::RunOptions opt;
      opt.outdir = dir;
      opt.until = sc.until;
      opt.maxReplayFrames =
          0;  // a sweep keeps the numbers; `yardsim run` reproduces a case in full
      try {
        auto root = scene::assemble(sc);
        const run::RunResult res = run::runScene(sc, *root, opt);
        r.tEnd = res.tEnd;
        r.runWall = res.wall;
        r.status = "ok";
      } catch (const devs::SimulationError& e) {
        r.status = "failed";
        r.message = e.what();
      }
      r.collected = collectScalars(spec, dir / "timeseries.csv");
    }
  } catch (const std::exception& e) {
    r.status = "failed";
    r.message = e.what();
  }
  r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  writeCaseRecord(r, dir / "case.yaml");
  return r;
}

void writeCaseRecord(const CaseRecord& r, const fs::path& file) {
  YAML::Emitter e;
  e.SetDoublePrecision(17);
  e << YAML::BeginMap << YAML::Key << "id" << YAML::Value << r.id;
  e << YAML::Key << "values" << YAML::Value << YAML::Flow << YAML::BeginSeq;
  for (double v : r.values) e << v;
  e << YAML::EndSeq << YAML::Key << "status" << YAML::Value << r.status;
  e << YAML::Key << "message" << YAML::Value << YAML::DoubleQuoted << r.message;
  e << YAML::Key << "wall" << YAML::Value << r.wall << YAML::Key << "run_wall" << YAML::Value
    << r.runWall;
  e << YAML::Key << "t_end" << YAML::Value << r.tEnd;
  e << YAML::Key << "rank" << YAML::Value << r.rank;
  e << YAML::Key << "collected" << YAML::Value << YAML::Flow << YAML::BeginSeq;
  for (double v : r.collected) e << v;
  e << YAML::EndSeq << YAML::EndMap;
  fs::create_directories(file.parent_path());
  const fs::path tmp = file.string() + ".tmp";
  {
    std::ofstream os(tmp, std::ios::binary | std::ios::trunc);
    os << e.c_str() << "\n";
    if (!os) throw std::runtime_error("cannot write " + tmp.string());
  }
  fs::rename(tmp, file);
}

std::optional<CaseRecord> readCaseRecord(const fs::path& file) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) return std::nullopt;
  try {
    const YAML::Node n = YAML::LoadFile(file.string());
    CaseRecord r;
    r.id = n["id"].as<std::size_t>();
    for (const auto& v : n["values"]) r.values.push_back(v.as<double>());
    r.status = n["status"].as<std::string>();
    r.message = n["message"].as<std::string>();
    r.wall = n["wall"].as<double>();
    r.runWall = n["run_wall"].as<double>();
    r.tEnd = n["t_end"].as<double>();
    r.rank = n["rank"].as<int>();
    for (const auto& v : n["collected"]) r.collected.push_back(v.as<double>());
    return r;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace yardsim::studies
