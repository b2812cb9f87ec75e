#pragma once
// Loop-closure (cut-joint) constraints: residuals, Jacobian and acceleration bias, stacked in the
// order of model.loops. For loop c with frame F on body A and G on body B, the rows are the
// components selected by c.mask of
//   position: [rotation error of G relative to F; p_FG expressed in F]
//   velocity: R_WF^T [omega_B - omega_A; velocity of the point G on B - velocity of the same point on A]
// The rotation error is log(R_FG) when all three rotations are constrained and (-R_FG(1,2), R_FG(0,2))
// (z_F x z_G) for an axis constraint; both have derivative omega_FG in F on the constraint manifold.

#include <Eigen/Core>

#include "dynamics/data.hpp"
#include "dynamics/model.hpp"

namespace yardsim::dynamics {

/// (q) => data.residual (size nc), running forward kinematics.
const Eigen::VectorXd& loopResidual(const Model& model, Data& data, const Eigen::VectorXd& q);
/// (q) => data.J (nc x nv), and data.X_WB, data.S_W.
const Eigen::MatrixXd& loopJacobian(const Model& model, Data& data, const Eigen::VectorXd& q);
/// (q, v) => data.J, data.cv = J v and data.kappa with d/dt(J v) = J ddq + kappa.
void loopJacobianAndBias(const Model& model, Data& data, const Eigen::VectorXd& q, const Eigen::VectorXd& v);
/// (q) => max |g(q)| over all loop rows (0 without loops), leaving data.residual.
double loopResidualNorm(const Model& model, Data& data, const Eigen::VectorXd& q);

}  // namespace yardsim::dynamics
