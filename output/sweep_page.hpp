#pragma once
// OUT/sweep.html of `yardsim sweep` (docs/sweeps.md), drawn by the report bundle (kind
// "sweep"): the case table (sortable, filterable), each collected quantity against each varied
// parameter with its limit, the operability map (pass/fail over two varied parameters) and
// links to the per-case reports of the worst cases.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace yardsim::output {

struct SweepLimit {
  std::string collect;  // the collected column it bounds
  double bound = 0.0;   // in that quantity's unit
  bool upper = true;    // pass when value <= bound (else >= bound)
};

struct SweepRow {
  long long id = 0;
  std::vector<double> values;  // per varied parameter
  std::string status, message;
  double wall = 0.0;              // s
  std::vector<double> collected;  // per collected quantity (NaN: none)
  bool pass = false;              // ok and within every limit
  std::string link;               // a per-case report relative to the page, or empty
};

struct SweepPage {
  std::string title;
  std::vector<std::pair<std::string, std::string>> facts;
  std::vector<std::string> params, collect;
  std::vector<SweepLimit> limits;
  std::vector<std::string> operability;  // two of params, or empty
  std::vector<SweepRow> rows;
};

// (page) => the data JSON the bundle reads (kind "sweep"); NaN as null
std::string sweepJson(const SweepPage& page);
// (file, page) => the HTML page written
void writeSweepPage(const std::filesystem::path& file, const SweepPage& page);

}  // namespace yardsim::output
