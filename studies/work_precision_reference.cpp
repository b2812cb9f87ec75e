#include "studies/work_precision_reference.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "dtss/grid.hpp"

namespace yardsim::studies {
namespace {

std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream s(line);
  std::string c;
  while (std::getline(s, c, ',')) {
    const auto a = c.find_first_not_of(" \t\r\""), b = c.find_last_not_of(" \t\r\"");
    out.push_back(a == std::string::npos ? "" : c.substr(a, b - a + 1));
  }
  return out;
}

// (column header) => its name without a trailing "[unit]"
std::string bare(const std::string& header) {
  const auto bracket = header.rfind('[');
  return bracket != std::string::npos && header.back() == ']' ? header.substr(0, bracket) : header;
}

}  // namespace

WpSeries readReferenceSeries(const std::string& file, const WpSpec& spec) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file + ": cannot read the reference solution");
  // (file) => header, then rows of numbers
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
  std::string line;
  for (int lineNo = 1; std::getline(in, line); ++lineNo) {
    if (line.empty() || line[0] == '#' || line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const auto c = cells(line);
    if (header.empty()) {
      header = c;
      continue;
    }
    std::vector<double> row;
    for (const auto& x : c) {
      std::size_t used = 0;
      double v = 0.0;
      try {
        v = std::stod(x, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != x.size() || !std::isfinite(v))
        throw std::runtime_error(file + ":" + std::to_string(lineNo) + ": expected numbers, got '" + x + "'");
      row.push_back(v);
    }
    if (row.size() != header.size())
      throw std::runtime_error(file + ":" + std::to_string(lineNo) + ": expected " + std::to_string(header.size()) +
                               " values (as many as the header), got " + std::to_string(row.size()));
    if (!rows.empty() && !(row[0] > rows.back()[0]))
      throw std::runtime_error(file + ":" + std::to_string(lineNo) + ": times must increase");
    rows.push_back(std::move(row));
  }
  if (header.size() < 2 || rows.size() < 2)
    throw std::runtime_error(file + ": expected a header (time, channels...) and at least two rows");
  // (channels) => their columns
  std::vector<std::size_t> col;
  for (const auto& ch : spec.channels) {
    std::size_t found = 0;
    for (std::size_t j = 1; j < header.size() && !found; ++j)
      if (header[j] == ch || bare(header[j]) == ch) found = j;
    if (!found) throw std::runtime_error(file + ": no column for the error channel '" + ch + "'");
    col.push_back(found);
  }
  // (grid times) => values interpolated linearly between the rows around them
  WpSeries out;
  std::size_t i = 0;
  for (std::int64_t k = 0;; ++k) {
    const double t = k == 0 ? 0.0 : std::min(dtss::gridOffset(spec.interval, k), spec.until);
    const double slack = 1e-9 * spec.interval;
    if (t < rows.front()[0] - slack || t > rows.back()[0] + slack)
      throw std::runtime_error(file + ": the reference covers t = " + std::to_string(rows.front()[0]) + " .. " +
                               std::to_string(rows.back()[0]) + " s, not the grid time " + std::to_string(t) + " s");
    while (i + 2 < rows.size() && rows[i + 1][0] < t) ++i;
    const auto& a = rows[i];
    const auto& b = rows[i + 1];
    const double w = std::clamp((t - a[0]) / (b[0] - a[0]), 0.0, 1.0);
    std::vector<double> v;
    for (std::size_t c : col) v.push_back((1.0 - w) * a[c] + w * b[c]);
    out.values.push_back(std::move(v));
    if (t >= spec.until) break;
  }
  return out;
}

}  // namespace yardsim::studies
