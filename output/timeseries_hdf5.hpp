#pragma once
// A run's time series in HDF5 (`yardsim run --format hdf5` writes OUTDIR/timeseries.h5; a
// sweep with `series: true` puts each case's under /cases/<id>/ of sweep.h5): in a group, one
// float64 dataset per column ("time", then each channel by name) with its unit as attribute,
// and the '#' metadata of timeseries.csv as attributes of the group.
#include <filesystem>
#include <string>

#include "output/hdf5_file.hpp"
#include "output/timeseries_reader.hpp"

namespace yardsim::output {

// (file, group, series) => the group written
void writeTimeseriesGroup(Hdf5File& file, const std::string& group, const Timeseries& ts);

// (OUTDIR/timeseries.csv, file) => the file holding its series under /series
void writeTimeseriesHdf5(const std::filesystem::path& csv, const std::filesystem::path& file);

}  // namespace yardsim::output
