#pragma once
// A published reference solution for `yardsim wp` (docs/numerics.md): a CSV file whose first
// column is time (s) and whose other columns include the scene's error channels (named as in
// `yardsim list-channels`, with or without their "[unit]"), read and interpolated linearly onto
// the sweep's output grid. Lines starting with '#' are comments (a yardsim timeseries.csv works
// as it is).
#include <string>

#include "studies/work_precision.hpp"
#include "studies/work_precision_reader.hpp"

namespace yardsim::studies {

// (file, spec) => the reference on the grid t_k = k * interval up to until; throws
// std::runtime_error naming the file (and line) when it cannot be read, lacks a channel, or does
// not cover the grid
WpSeries readReferenceSeries(const std::string& file, const WpSpec& spec);

}  // namespace yardsim::studies
