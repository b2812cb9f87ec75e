#pragma once
// OUTDIR/timeseries.csv: '#' metadata lines (yardsim version, scene file and SHA-256,
// integrator, step, seed), a header `time[s],<channel>[<unit>],...`, then one row per sample.
// Rows are flushed as the run goes (at least every 0.2 s of wall time, and when the writer is
// destroyed), so a run that fails keeps every sample taken before the failure.
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "devs/buffered_file.hpp"
#include "models/channels.hpp"
#include "scene/scene.hpp"

namespace yardsim::run {

using models::Channel;
using scene::Scene;

class TimeseriesWriter {
 public:
  // (file, scene, channels, the checkpoint a restarted run continues from: a
  // "# restarted_from <file> at <t> s" line in the metadata) => the header written
  TimeseriesWriter(const std::filesystem::path& file, const Scene& scene,
                   std::vector<Channel> channels, const std::string& restartedFrom = {});
  ~TimeseriesWriter();
  // (t) => one row: t and every channel read now
  void sample(double t);
  std::size_t rows() const { return rows_; }

 private:
  devs::BufferedFile file_;
  std::ofstream& out_ = file_.stream();
  std::vector<Channel> channels_;
  std::string line_;
  // per channel, the last value written and its text (a channel often holds still for many rows;
  // keyed by the bits, so -0 and 0 stay apart)
  struct Cell {
    std::uint64_t bits = 0;
    char text[32] = {};
    unsigned char length = 0;  // 0: none
  };
  std::vector<Cell> last_;
  std::size_t rows_ = 0;
  std::chrono::steady_clock::time_point lastFlush_;
};

// (value) => shortest text that reads back to the same double ("nan", "inf" for non-finite)
void appendCsvNumber(std::string& out, double value);

extern const char* const kVersion;

}  // namespace yardsim::run
