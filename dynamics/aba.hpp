#pragma once
// Forward dynamics by the articulated-body algorithm, O(n) (Featherstone, table 7.1).

#include <Eigen/Core>

#include "dynamics/data.hpp"
#include "dynamics/external_forces.hpp"
#include "dynamics/model.hpp"

namespace yardsim::dynamics {

/// (q, v, tau, external forces) => data.ddq with M ddq + h = tau + sum J_i^T F_ext_i.
/// Also leaves data.X_PB, data.V, data.C, data.IA and data.A (which includes -g).
const Eigen::VectorXd& aba(const Model& model, Data& data, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                           const Eigen::VectorXd& tau, const ExternalForces* fext = nullptr);

}  // namespace yardsim::dynamics
