#pragma once
// The structure of the acceleration's Jacobian d(dv/dt)/d(q, v) and a colouring of its columns
// (Curtis, Powell & Reid 1974): two columns (dofs) may share a colour when no acceleration depends
// on both, so one perturbation of every column of a colour gives all their entries at once. A
// chain of point masses coupled to its neighbours (a lumped-mass line) needs 3 node colours per
// line, whatever its length; lines that share no body share colours. Sizes are dofs (nv); the
// pattern is structural (an entry that may be non-zero somewhere), the same for q and v.
#include <array>
#include <vector>

namespace yardsim::dynamics {

// Per column j (a dof): the rows i (dofs) whose acceleration may depend on q_j or v_j, sorted,
// j itself included. A row left out is a promise that the entry is zero at every state.
struct JacobianPattern {
  int n = 0;
  std::vector<std::vector<int>> rows;
};

// The 3x3 blocks of d(dv/dt)/dq and d(dv/dt)/dv that a system gives in closed form (a lumped
// line's nodes among themselves): per block the first row and the first column (dofs). Each
// block lies inside the pattern; a column all of whose pattern rows lie in blocks needs no
// finite difference.
struct JacobianBlocks {
  std::vector<std::array<int, 2>> at;
  // 3 x 1 blocks (rows r0 .. r0 + 2 of column c0: a line's end node coupled to a rigid dof of
  // the body at the line's end), their values in the first column of the Matrix3 after the
  // at.size() square ones; they do not take their columns out of the colouring (the column's
  // other rows are still differenced) and are left out where the pattern has no such entries
  std::vector<std::array<int, 2>> columns;
};

// Per column its colour in [0, count), and per colour its columns (increasing).
struct ColumnColouring {
  std::vector<int> colour;
  std::vector<std::vector<int>> columns;
  int count() const { return static_cast<int>(columns.size()); }
};

// (pattern) => a colouring by the greedy rule, columns in order: each takes the smallest colour
// that none of the columns sharing a row with it holds
ColumnColouring colourColumns(const JacobianPattern& pattern);

// (pattern, colouring) => the first row that two columns of one colour touch, or -1 when the
// colouring is valid (also -1 only if every column has a colour in range)
int colouringConflict(const JacobianPattern& pattern, const ColumnColouring& colouring);

}  // namespace yardsim::dynamics
