#pragma once
// The structure of a mechanical system's acceleration Jacobian d(dv/dt)/d(q, v), for the implicit
// integrators' sparse Newton matrix (dynamics/integrators/sparse_newton_matrix.hpp). A system with
// lumped-mass lines (forces/lines/lumped_line_provider.hpp) has it: an inner node is a point mass
// on its own joint from the world whose force comes from its line alone, so its acceleration
// depends on itself and its two neighbours (four: two on each side, for a line with bending
// stiffness EI > 0). Everything else (the rigid bodies' dofs, through ABA, the loops and every
// other provider) is taken as coupled to everything rigid, and a node next to a body (the
// fairlead's, the anchor's; with bending, within two nodes of it) as coupled to every rigid dof. A node that anything else
// names (a rope, a load, another provider's attachment, a loop, a child body, a geometry) counts
// as rigid. Sizes: dofs (nv).
#include <memory>
#include <vector>

#include "dynamics/integrators/column_colouring.hpp"
#include "forces/lines/lumped_line_provider.hpp"
#include "mechanics/system.hpp"

namespace yardsim::mechanics {

// (provider) => the lumped line it is, or wraps with its channels (the mooring reader's), or
// nullptr
const forces::LumpedLineProvider* lumpedLine(const forces::ForceProvider& p);
// (system) => per body: 1 for a lumped line's inner node that the pattern couples to its
// neighbours only (on its own joint from the world, named by nothing else), else 0
std::vector<char> lineNodes(const System& s);

// (system) => its pattern, or nullptr when it has no lumped-line node (the dense path)
std::shared_ptr<const dynamics::JacobianPattern> jacobianPattern(const System& s);

}  // namespace yardsim::mechanics
