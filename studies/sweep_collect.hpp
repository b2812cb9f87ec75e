#pragma once
// The sweep's folder OUT (docs/sweeps.md): OUT/plan.yaml names the sweep file and its hash so a
// resume, an array task or --collect works on the same cases; OUT/cases/<id>/case.yaml are the
// case records every engine writes; the results gathered from them are OUT/cases.csv,
// OUT/sweep.h5 (the case table, optionally each case's time series) and OUT/sweep.html.
#include <filesystem>
#include <string>
#include <vector>

#include "studies/sweep_case.hpp"

namespace yardsim::studies {

// (spec, OUT) => OUT/plan.yaml written, or a runtime_error when OUT holds another sweep's plan
void writePlan(const SweepSpec& spec, const std::filesystem::path& out);
// (OUT) => the sweep file its plan names; runtime_error when OUT has no plan
std::filesystem::path planSweepFile(const std::filesystem::path& out);

// (spec, cases, OUT) => per case its record, or a record with status "missing"
std::vector<CaseRecord> gatherRecords(const SweepSpec& spec, const std::vector<SweepCase>& cases,
                                      const std::filesystem::path& out);

// (spec, record) => ok and within every limit
bool passes(const SweepSpec& spec, const CaseRecord& r);

struct SweepCounts {
  std::size_t total = 0, ok = 0, failed = 0, missing = 0, passed = 0;
};
// (spec, records, OUT) => OUT/cases.csv, OUT/sweep.h5, OUT/sweep.html; the counts
SweepCounts writeSweepResults(const SweepSpec& spec, const std::vector<CaseRecord>& records,
                              const std::filesystem::path& out);

}  // namespace yardsim::studies
