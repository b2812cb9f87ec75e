#pragma once
// A parameter sweep (`yardsim sweep SWEEP.yaml`, docs/sweeps.md): the scene, the root `params:`
// it varies and how (grid, latin hypercube, list), the scalars collected from each case's
// recorded channels, the limits that decide pass or fail, and the per-case time-out. Read and
// checked at the door with file:line:col; expanded into the numbered list of cases.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "models/diagnostics.hpp"

namespace yardsim::studies {

using models::Diagnostics;
using models::SourceMark;

// One varied root parameter and the values it takes (grid, list) or its range (latin hypercube).
struct SweepParam {
  std::string name;             // a root `params:` name, or `seed` (the scene's seed)
  std::vector<double> values;   // in the parameter's own unit; for a range: its grid from..to
  double from = 0.0, to = 0.0;  // the range a latin hypercube samples (min and max of values)
  bool integer = false;         // a seed or a list of whole numbers: written without a fraction
  bool sceneSeed = false;       // `seed` where the scene declares no such param: the scene's seed
  SourceMark where;
};

// One collected scalar: op(glob) over every recorded channel matching glob and every sample.
struct CollectSpec {
  std::string text;  // "max(GOC*.tension)", the column name
  std::string op;    // max | min | absmax | mean | final
  std::string glob;  // over channel names
  SourceMark where;
};

// A limit on a collected scalar: pass when value <= bound (upper) or >= bound (lower).
struct LimitSpec {
  std::string collect;  // the CollectSpec text it applies to
  double bound = 0.0;
  bool upper = true;
  SourceMark where;
};

struct SweepSpec {
  std::filesystem::path file;   // the sweep file
  std::filesystem::path scene;  // resolved against the sweep file's folder
  std::string mode = "grid";    // grid | latin_hypercube | list
  std::size_t samples = 0;      // latin_hypercube: number of cases
  std::uint64_t seed = 1;       // latin_hypercube: its sampling seed
  std::vector<SweepParam> params;
  std::vector<CollectSpec> collect;
  std::vector<LimitSpec> limits;
  double caseTimeout = 0.0;              // s of wall time per case; 0: none
  std::vector<std::string> operability;  // two varied parameter names for the report's map
  bool series = false;  // also each case's time series in sweep.h5 under /cases/<id>/
};

// One case: its number (0-based, stable for a given sweep file) and a value per varied param.
struct SweepCase {
  std::size_t id = 0;
  std::vector<double> values;  // in SweepSpec::params order
};

// (sweep file) => the spec; every mistake in diags with file:line:col
SweepSpec readSweepSpec(const std::filesystem::path& file, Diagnostics& diags);

// (spec) => every case, numbered in order (grid: the last parameter varies fastest)
std::vector<SweepCase> expandCases(const SweepSpec& spec);

// (value, integer) => its text as a scene parameter and in tables ("3", "0.25", 17 digits)
std::string formatValue(double value, bool integer);

}  // namespace yardsim::studies
