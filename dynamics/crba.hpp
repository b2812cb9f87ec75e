#pragma once
// The joint-space mass matrix by the composite-rigid-body algorithm in the world frame (H_ki =
// S_k^T IC_k S_i for k in the subtree of i, one product per dof over its contiguous subtree rows).
// A composite inertia is kept as its 10 numbers (mass, first moment, rotational inertia about the
// world origin), a point mass written as added mass at a body origin included; any other added
// mass makes every composite a 6x6 matrix (crba.cpp).

#include <Eigen/Core>

#include "dynamics/data.hpp"
#include "dynamics/model.hpp"

namespace yardsim::dynamics {

/// (q) => data.M (both triangles), and data.X_WB, data.S_W (data.IC_W, data.Fcrb: scratch).
const Eigen::MatrixXd& crba(const Model& model, Data& data, const Eigen::VectorXd& q);

}  // namespace yardsim::dynamics
