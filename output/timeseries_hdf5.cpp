#include "output/timeseries_hdf5.hpp"

namespace yardsim::output {

void writeTimeseriesGroup(Hdf5File& file, const std::string& group, const Timeseries& ts) {
  file.group(group);
  for (const auto& [key, value] : ts.meta) file.attribute(group, key, value);
  for (std::size_t c = 0; c < ts.columns.size(); ++c) {
    const std::string path = group + "/" + (c == 0 ? std::string("time") : ts.columns[c].name);
    file.doubles(path, ts.columns[c].values);
    file.attribute(path, "unit", ts.columns[c].unit);
  }
}

void writeTimeseriesHdf5(const std::filesystem::path& csv, const std::filesystem::path& file) {
  const Timeseries ts = readTimeseries(csv);
  Hdf5File h(file);
  writeTimeseriesGroup(h, "/series", ts);
}

}  // namespace yardsim::output
