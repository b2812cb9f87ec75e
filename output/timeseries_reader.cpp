#include "output/timeseries_reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <stdexcept>

namespace yardsim::output {

Timeseries readTimeseries(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read '" + file.string() + "'");
  Timeseries ts;
  std::string line;
  std::size_t lineNo = 0;
  auto fail = [&](const std::string& what) {
    throw std::runtime_error(file.string() + ":" + std::to_string(lineNo) + ": " + what);
  };
  while (std::getline(in, line)) {
    ++lineNo;
    if (line.empty()) continue;
    if (line[0] == '#') {
      // ("# key value") => metadata
      const auto key = line.find_first_not_of("# ");
      const auto sp = line.find(' ', key);
      if (key != std::string::npos)
        ts.meta[line.substr(key, sp - key)] = sp == std::string::npos ? "" : line.substr(sp + 1);
      continue;
    }
    if (ts.columns.empty()) {
      // ("name[unit],...") => columns
      std::size_t start = 0;
      while (start <= line.size()) {
        const auto end = std::min(line.find(',', start), line.size());
        const std::string cell = line.substr(start, end - start);
        const auto open = cell.rfind('[');
        if (open == std::string::npos || cell.back() != ']') fail("expected a header cell name[unit], got '" + cell + "'");
        ts.columns.push_back({cell.substr(0, open), cell.substr(open + 1, cell.size() - open - 2), {}});
        start = end + 1;
      }
      continue;
    }
    // (row) => one value per column; nan and inf as written by appendCsvNumber
    const char* p = line.data();
    const char* end = p + line.size();
    for (std::size_t c = 0; c < ts.columns.size(); ++c) {
      double v = 0.0;
      const char* comma = std::find(p, end, ',');
      const std::string_view cell(p, static_cast<std::size_t>(comma - p));
      if (cell == "nan") v = std::numeric_limits<double>::quiet_NaN();
      else if (cell == "inf") v = std::numeric_limits<double>::infinity();
      else if (cell == "-inf") v = -std::numeric_limits<double>::infinity();
      else if (std::from_chars(p, comma, v).ptr != comma) fail("expected a number, got '" + std::string(cell) + "'");
      ts.columns[c].values.push_back(v);
      if (comma == end && c + 1 < ts.columns.size()) fail("expected " + std::to_string(ts.columns.size()) + " cells");
      p = comma == end ? end : comma + 1;
    }
  }
  if (ts.columns.empty()) throw std::runtime_error("'" + file.string() + "' has no header line");
  return ts;
}

}  // namespace yardsim::output
