#pragma once
// The closed-form blocks of a system's acceleration Jacobian d(dv/dt)/d(q, v): per lumped line
// (forces/lines/lumped_line_provider.hpp) the 3x3 blocks d a_i/d r_j (1/s^2) and d a_i/d v_j
// (1/s) among its inner nodes that the pattern (jacobian_pattern.hpp) couples to their
// neighbours only, j = i - 1, i, i + 1 (i - 2 .. i + 2 for a line with bending stiffness). The
// implicit integrators' sparse Newton matrix (dynamics/integrators/sparse_newton_matrix.hpp)
// writes them instead of finite differences and re-evaluates them at every Newton iterate. Rows and columns are dofs (nv), world frame.
#include <memory>

#include "dynamics/multibody_system.hpp"
#include "mechanics/data.hpp"
#include "mechanics/system.hpp"

namespace yardsim::mechanics {

struct LineJacobian {
  std::shared_ptr<const dynamics::JacobianBlocks> blocks;  // nullptr: no line node
  dynamics::MultibodySystem::BlockCallback evaluate;       // its values at a state
};

// (system, its data: the providers' scratch) => the blocks and their evaluation; data must
// outlive the callback. The evaluation allocates nothing.
LineJacobian lineJacobian(const System& s, const Data& d);

}  // namespace yardsim::mechanics
