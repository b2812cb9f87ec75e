#pragma once
// The closed-form blocks of a system's acceleration Jacobian d(dv/dt)/d(q, v): per lumped line
// (forces/lines/lumped_line_provider.hpp) the 3x3 blocks d a_i/d r_j (1/s^2) and d a_i/d v_j
// (1/s) among its inner nodes that the pattern (jacobian_pattern.hpp) couples to their
// neighbours only, j = i - 1, i, i + 1 (i - 2 .. i + 2 for a line with bending stiffness); and
// per end on a body (not a node) the 3 x 1 blocks d a_i/d q_c and d a_i/d v_c (1/s^2, 1/s per
// m or rad) of the inner nodes within that reach of the end, for every dof c from the body down
// to the world: d a_i/d r_end J_c, J_c = v_O + omega x p_end of joint c's world subspace column
// (the end point's velocity per unit v_c; for a free joint, the chart's derivative at zero). The
// implicit integrators' sparse Newton matrix (dynamics/integrators/sparse_newton_matrix.hpp)
// writes them instead of finite differences and re-evaluates them at every Newton iterate (and
// CVODE at every setup), so the rigid dofs' differenced columns age only in their other rows.
// Rows and columns are dofs (nv), world frame.
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
