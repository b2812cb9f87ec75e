#pragma once
// Reads OUTDIR/timeseries.csv back (as TimeseriesWriter writes it): the '#' metadata lines,
// and per column its channel name, unit and values.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace yardsim::output {

struct TimeseriesColumn {
  std::string name, unit;  // "pendulum.joint0.q", "rad"; the first column is time, "s"
  std::vector<double> values;
};

struct Timeseries {
  std::map<std::string, std::string> meta;  // "# key value"
  std::vector<TimeseriesColumn> columns;    // columns[0]: time
};

// (file) => its contents; throws std::runtime_error naming the file and line on bad content
Timeseries readTimeseries(const std::filesystem::path& file);

}  // namespace yardsim::output
