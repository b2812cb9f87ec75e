#pragma once
// One case of a sweep, in this process: the scene loaded with the case's root params, assembled
// and run into OUT/cases/<id>/ (timeseries.csv, run.json), its scalars collected from what it
// recorded, and its record written atomically to OUT/cases/<id>/case.yaml — the state that
// resume, every engine and --collect read back. A case that fails is recorded, never thrown.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "studies/sweep_spec.hpp"

namespace yardsim::studies {

struct CaseRecord {
  std::size_t id = 0;
  std::vector<double> values;  // the varied params, SweepSpec::params order
  std::string status =
      "missing";         // ok | failed (numerical) | refused (scene) | timeout | crashed | missing
  std::string message;   // the diagnosis when not ok
  double wall = 0.0;     // s: load, assembly, run and collection of the case
  double runWall = 0.0;  // s: the run alone (run::RunResult::wall)
  double tEnd = 0.0;     // s simulated
  std::vector<double> collected;  // SweepSpec::collect order; NaN where nothing was recorded
  int rank = 0;                   // the MPI rank or array task that ran it
};

// (OUT, id) => OUT/cases/<id> with the id zero-padded to 6 digits
std::filesystem::path caseDir(const std::filesystem::path& out, std::size_t id);

// (spec, case, OUT, rank) => the case run and recorded in caseDir(OUT, id)/case.yaml
CaseRecord runCase(const SweepSpec& spec, const SweepCase& c, const std::filesystem::path& out,
                   int rank);

// (spec, case) => the scene's diagnostics with this case's params (errors point into the sweep
// file where a varied name is no root param); empty when it loads
models::Diagnostics checkCase(const SweepSpec& spec, const SweepCase& c);

// (record, file) => written to file.tmp then renamed, so a kill never leaves half a record
void writeCaseRecord(const CaseRecord& r, const std::filesystem::path& file);
// (file) => the record, or nullopt when absent or unreadable (a case to run again)
std::optional<CaseRecord> readCaseRecord(const std::filesystem::path& file);

// (spec, series of a run) => op(glob) of every collect spec over the recorded channels
std::vector<double> collectScalars(const SweepSpec& spec,
                                   const std::filesystem::path& timeseriesCsv);

}  // namespace yardsim::studies
