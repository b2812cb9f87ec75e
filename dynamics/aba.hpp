#pragma once
// Forward dynamics by the articulated-body algorithm, O(n) (Featherstone, table 7.1), written in
// the world frame: articulated inertias and bias forces are accumulated in world coordinates, so
// passing them to the parent is an addition rather than a Plücker transform (as in Pinocchio 3).

#include <Eigen/Core>

#include "dynamics/data.hpp"
#include "dynamics/external_forces.hpp"
#include "dynamics/model.hpp"

namespace yardsim::dynamics {

/// (q, v, tau, external forces) => data.ddq with M ddq + h = tau + sum J_i^T F_ext_i.
/// Also leaves data.X_PB, data.X_WB, data.S_W, data.V_W, data.C_W, data.IA_W (world frame; its
/// lower block triangle, the 2x2 blocks on and below the diagonal: the 1-dof joints leave the upper
/// blocks stale) and data.A_W (world frame, including -g: add g to the linear part for
/// the true acceleration).
const Eigen::VectorXd& aba(const Model& model, Data& data, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                           const Eigen::VectorXd& tau, const ExternalForces* fext = nullptr);

/// The same, for a data that already holds forwardKinematics(q, ...) (X_PB, X_WB): the joint
/// placements are not computed again (one kinematics pass per integrator stage). Same results
/// to the last bit as aba().
const Eigen::VectorXd& abaAfterKinematics(const Model& model, Data& data, const Eigen::VectorXd& q,
                                          const Eigen::VectorXd& v, const Eigen::VectorXd& tau,
                                          const ExternalForces* fext = nullptr);

}  // namespace yardsim::dynamics
