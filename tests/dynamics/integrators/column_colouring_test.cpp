// The column colouring of a Jacobian pattern: chains of 3-dof point masses (lumped-line nodes)
// need 3 node colours (9 dof colours) whatever their length, chains that share no body share
// colours, dofs next to a dense rigid block get their own, and the check finds a colouring that
// lets two columns of one colour touch one row.
#include <catch2/catch.hpp>

#include <algorithm>
#include <set>

#include "dynamics/integrators/column_colouring.hpp"

using namespace yardsim::dynamics;

namespace {

// (rigid dofs r, lines of n nodes of 3 dofs, the last node of each line next to the rigid block)
// => the pattern: rigid dofs dense among themselves and with the last nodes; each node coupled to
// itself and its neighbours
JacobianPattern linesPattern(int r, int lines, int n, bool attached) {
  JacobianPattern p;
  p.n = r + 3 * lines * n;
  p.rows.resize(static_cast<std::size_t>(p.n));
  std::vector<int> rigid, touching;
  for (int i = 0; i < r; ++i) rigid.push_back(i);
  auto dofs = [&](int line, int node, std::vector<int>& out) {
    for (int k = 0; k < 3; ++k) out.push_back(r + 3 * (line * n + node) + k);
  };
  for (int l = 0; l < lines && attached; ++l) dofs(l, n - 1, touching);
  for (int i = 0; i < r; ++i) {
    auto& rows = p.rows[static_cast<std::size_t>(i)];
    rows = rigid;
    rows.insert(rows.end(), touching.begin(), touching.end());
  }
  for (int l = 0; l < lines; ++l)
    for (int k = 0; k < n; ++k) {
      std::vector<int> rows;
      for (int o = std::max(0, k - 1); o <= std::min(n - 1, k + 1); ++o) dofs(l, o, rows);
      if (attached && k == n - 1) rows.insert(rows.end(), rigid.begin(), rigid.end());
      std::sort(rows.begin(), rows.end());
      for (int d = 0; d < 3; ++d) p.rows[static_cast<std::size_t>(r + 3 * (l * n + k) + d)] = rows;
    }
  return p;
}

}  // namespace

TEST_CASE("a free chain of point masses needs 9 colours whatever its length") {
  for (int n : {3, 10, 40, 200}) {
    const JacobianPattern p = linesPattern(0, 1, n, false);
    const ColumnColouring c = colourColumns(p);
    CHECK(c.count() == 9);
    CHECK(colouringConflict(p, c) == -1);
  }
}

TEST_CASE("lines that share no body share colours - those next to the rigid block get their own") {
  // 8 lines of 19 nodes on a 2-dof buoy: the 2 rigid dofs, the 8 last nodes (24 dofs) distinct,
  // the other nodes fit in the colours already there (9 at most beyond the shared ones)
  const JacobianPattern p = linesPattern(2, 8, 19, true);
  const ColumnColouring c = colourColumns(p);
  CHECK(colouringConflict(p, c) == -1);
  CHECK(c.count() >= 2 + 24);
  CHECK(c.count() <= 2 + 24 + 9);
  std::set<int> touching;
  for (int i = 0; i < 2; ++i) touching.insert(c.colour[static_cast<std::size_t>(i)]);
  for (int l = 0; l < 8; ++l)
    for (int d = 0; d < 3; ++d)
      touching.insert(c.colour[static_cast<std::size_t>(2 + 3 * (l * 19 + 18) + d)]);
  CHECK(touching.size() == 26u);
  // free lines: the same 9 colours for all of them
  CHECK(colourColumns(linesPattern(0, 8, 19, false)).count() == 9);
}

TEST_CASE("every column of a colour is listed under it and the colours cover all columns") {
  const JacobianPattern p = linesPattern(3, 4, 7, true);
  const ColumnColouring c = colourColumns(p);
  int listed = 0;
  for (int k = 0; k < c.count(); ++k)
    for (int j : c.columns[static_cast<std::size_t>(k)]) {
      CHECK(c.colour[static_cast<std::size_t>(j)] == k);
      ++listed;
    }
  CHECK(listed == p.n);
}

TEST_CASE("a broken colouring is found - two neighbouring nodes in one colour touch a shared row") {
  const JacobianPattern p = linesPattern(0, 1, 5, false);
  ColumnColouring c = colourColumns(p);
  REQUIRE(colouringConflict(p, c) == -1);
  // node 1's x joins node 2's x's colour: both touch the rows of nodes 1 and 2
  const int from = c.colour[3], to = c.colour[6];
  REQUIRE(from != to);
  auto& old = c.columns[static_cast<std::size_t>(from)];
  old.erase(std::find(old.begin(), old.end(), 3));
  c.columns[static_cast<std::size_t>(to)].push_back(3);
  c.colour[3] = to;
  const int row = colouringConflict(p, c);
  CHECK(row >= 0);
  CHECK(row < 9);  // a dof of node 0, 1 or 2 (nodes 1 and 2 share rows of nodes 1 and 2)
  // a column left without a colour is a conflict too
  c.colour[3] = -1;
  CHECK(colouringConflict(p, c) >= 0);
}

TEST_CASE("a dense pattern gets one colour per column") {
  JacobianPattern p;
  p.n = 6;
  for (int j = 0; j < 6; ++j) p.rows.push_back({0, 1, 2, 3, 4, 5});
  const ColumnColouring c = colourColumns(p);
  CHECK(c.count() == 6);
  CHECK(colouringConflict(p, c) == -1);
}
