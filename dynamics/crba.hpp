#pragma once
// The joint-space mass matrix by the composite-rigid-body algorithm in the world frame (H_ca =
// S_a^T IC_c S_c for a = c and every ancestor dof a of c: one row of M per dof, along its
// ancestors). A composite inertia is kept as its 10 numbers (mass, first moment, rotational inertia
// about the world origin), a point mass written as added mass at a body origin included; a floating
// base (body 1 on a free joint at the world) takes its 6x6 block from its composite and its entries
// against each dof below it from one force transform; any other added mass makes every composite a
// 6x6 matrix (crba.cpp).

#include <Eigen/Core>

#include "dynamics/data.hpp"
#include "dynamics/model.hpp"

namespace yardsim::dynamics {

/// (q) => data.M (both triangles), and data.X_WB, data.S_W (data.IC_W, data.Fcrb: scratch).
const Eigen::MatrixXd& crba(const Model& model, Data& data, const Eigen::VectorXd& q);

}  // namespace yardsim::dynamics
