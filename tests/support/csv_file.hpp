#pragma once
// Test support: read a time-series CSV (with '#' metadata lines) back.
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace yardsim::testing {

struct CsvFile {
  std::map<std::string, std::string> meta;  // "# key value" lines
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;

  explicit CsvFile(const std::string& path) {
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
      if (line.rfind("# ", 0) == 0) {
        const auto sp = line.find(' ', 2);
        meta[line.substr(2, sp - 2)] = sp == std::string::npos ? "" : line.substr(sp + 1);
        continue;
      }
      std::vector<std::string> cells;
      std::stringstream ss(line);
      std::string cell;
      while (std::getline(ss, cell, ',')) cells.push_back(cell);
      if (header.empty()) {
        header = cells;
        continue;
      }
      std::vector<double> row;
      for (const auto& c : cells) row.push_back(std::stod(c));
      rows.push_back(row);
    }
  }
  // (column name) => its index in header, or -1
  int column(const std::string& name) const {
    for (std::size_t i = 0; i < header.size(); ++i)
      if (header[i] == name) return static_cast<int>(i);
    return -1;
  }
};

}  // namespace yardsim::testing
