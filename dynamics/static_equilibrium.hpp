#pragma once
// The configuration at which a system at rest stays at rest: accelerations zero with v = 0,
// found by Newton's method in the tangent space of the configuration manifold (joint-aware
// increments, quaternions stay unit) with a finite-difference Jacobian J = da/dx and a
// backtracking (Levenberg-Marquardt) search. Each step is rank-revealing: the singular value
// decomposition of J splits the tangent space into directions with stiffness (singular values
// above rankTolerance times the largest) and directions without (its null space: the sway, surge
// and yaw of an unmoored barge); the step solves only in the stiff subspace and leaves the
// others exactly where they are, unless a net force acts along them (a block falling onto a
// slack rope), when they move along that force until something stiff is met or the search gives
// up. Used to start a scene in static equilibrium (a block hanging still on its ropes) instead of
// releasing it from the unstretched geometry.

#include <Eigen/Core>
#include <string_view>
#include <vector>

#include "dynamics/integrators/integrator.hpp"
#include "dynamics/model.hpp"

namespace yardsim::dynamics {

struct EquilibriumOptions {
  double tolerance = 1e-9;   // on max |a| (m/s^2 or rad/s^2)
  int maxIterations = 50;
  double step = 1e-7;        // finite-difference increment in tangent coordinates
  int maxNeutralSteps = 20;  // moves in a row that leave the residual as it is (a fall onto slack ropes)
  /// A singular value of the Jacobian below rankTolerance x max(the largest, 1 s^-2) is a
  /// direction without stiffness. Above the finite-difference noise of J (1e-8 relative measured
  /// with the step above) and below the softest stiffness a scene has next to its stiffest (the
  /// sway of a hanging block, g / L, beside its wire rope's EA / (L m): about 1e-4).
  double rankTolerance = 1e-6;
};

/// A direction without stiffness that carries a net force: the tangent coordinate it is named by
/// (model.dofBody[dof] is its body) and the generalized force along it (N, or N m for a rotation).
struct UnbalancedDirection {
  int dof = 0;
  double force = 0.0;
};

struct EquilibriumResult {
  bool converged = false;
  int iterations = 0;
  double residual = 0.0;  // max |a| at the returned configuration
  int rank = 0;  // of J at the last iteration; when not converged, at the initial q (model.nv:
                 // every direction stiff)
  /// Found only by the minimum-norm search of before, from the initial q, after the rank-revealing
  /// one stalled: directions without stiffness may have moved.
  bool minimumNorm = false;
  /// When not converged: the directions without stiffness at the initial configuration along
  /// which a net force acts (why there is no equilibrium: a wind on an unmoored barge). The
  /// returned configuration is where the search stopped, possibly far along such a direction.
  std::vector<UnbalancedDirection> unbalanced;
};

/// (joint type, k < its nv) => the name of its k-th velocity direction: "surge (x)" .. "yaw (rz)"
/// for a free joint (body axes, naval names), "rotation" / "translation" for 1-dof joints, ...
std::string_view jointDirectionName(JointType type, int k);
/// (joint type, k < its nv) => true when its k-th velocity direction is a rotation (force in N m).
bool jointDirectionIsRotation(JointType type, int k);

/// (model, accelerations of the system with its forces, t, q) => q moved to static equilibrium.
/// Directions with no stiffness and no net force stay exactly where they are.
EquilibriumResult solveStaticEquilibrium(const Model& model, AccelerationSource& system, double t,
                                         Eigen::VectorXd& q, const EquilibriumOptions& options = {});

}  // namespace yardsim::dynamics
