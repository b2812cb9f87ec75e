#include "dynamics/integrators/column_colouring.hpp"

#include <stdexcept>

namespace yardsim::dynamics {

namespace {

// (pattern) => per row the columns that touch it
std::vector<std::vector<int>> columnsOfRows(const JacobianPattern& p) {
  std::vector<std::vector<int>> out(static_cast<std::size_t>(p.n));
  for (int j = 0; j < p.n; ++j)
    for (int i : p.rows[static_cast<std::size_t>(j)]) {
      if (i < 0 || i >= p.n) throw std::invalid_argument("JacobianPattern: row out of range");
      out[static_cast<std::size_t>(i)].push_back(j);
    }
  return out;
}

}  // namespace

ColumnColouring colourColumns(const JacobianPattern& p) {
  // (columns in order) => the smallest colour not held by a column that shares a row
  if (static_cast<int>(p.rows.size()) != p.n)
    throw std::invalid_argument("JacobianPattern: one row list per column expected");
  const auto byRow = columnsOfRows(p);
  ColumnColouring c;
  c.colour.assign(static_cast<std::size_t>(p.n), -1);
  std::vector<int> takenBy(static_cast<std::size_t>(p.n) + 1,
                           -1);  // per colour: the last column that found it taken
  for (int j = 0; j < p.n; ++j) {
    for (int i : p.rows[static_cast<std::size_t>(j)])
      for (int k : byRow[static_cast<std::size_t>(i)]) {
        const int ck = c.colour[static_cast<std::size_t>(k)];
        if (ck >= 0) takenBy[static_cast<std::size_t>(ck)] = j;
      }
    int colour = 0;
    while (takenBy[static_cast<std::size_t>(colour)] == j) ++colour;
    c.colour[static_cast<std::size_t>(j)] = colour;
    if (colour == c.count()) c.columns.emplace_back();
    c.columns[static_cast<std::size_t>(colour)].push_back(j);
  }
  return c;
}

int colouringConflict(const JacobianPattern& p, const ColumnColouring& c) {
  // (rows) => a row whose columns repeat a colour
  const auto byRow = columnsOfRows(p);
  std::vector<int> seenAt(static_cast<std::size_t>(c.count()), -1);
  for (int j = 0; j < p.n; ++j) {
    const int cj = c.colour[static_cast<std::size_t>(j)];
    if (cj < 0 || cj >= c.count())
      return p.rows[static_cast<std::size_t>(j)].empty() ? 0
                                                         : p.rows[static_cast<std::size_t>(j)][0];
  }
  for (int i = 0; i < p.n; ++i)
    for (int k : byRow[static_cast<std::size_t>(i)]) {
      int& seen = seenAt[static_cast<std::size_t>(c.colour[static_cast<std::size_t>(k)])];
      if (seen == i) return i;
      seen = i;
    }
  return -1;
}

}  // namespace yardsim::dynamics
