#pragma once
// Kinetic and potential energy, centre of mass, and the spatial momentum of the whole system.

#include <Eigen/Core>

#include "dynamics/data.hpp"
#include "dynamics/model.hpp"

namespace yardsim::dynamics {

/// (body i, its spatial velocity V in the body frame, the added mass in data) => 1/2 V . (I_i +
/// A_i) V, the kinetic energy of the body and of the fluid it carries along (A_i its added mass, if
/// any).
inline double bodyKineticEnergy(const Model& model, const Data& data, int i, const Motion& V) {
  double T = 0.5 * V.dot(model.inertias[static_cast<std::size_t>(i)].apply(V));
  if (data.hasAddedMass[static_cast<std::size_t>(i)])
    T += 0.5 * V.dot(data.addedMass[static_cast<std::size_t>(i)] * V);
  return T;
}
/// (q, v) => T = 1/2 sum V_i . (I_i + A_i) V_i, A_i the added mass (body and fluid; runs forward kinematics).
double kineticEnergy(const Model& model, Data& data, const Eigen::VectorXd& q, const Eigen::VectorXd& v);
/// (q) => U = - sum m_i g . c_i (gravity potential, zero at the world origin; runs forward kinematics).
double potentialEnergy(const Model& model, Data& data, const Eigen::VectorXd& q);
/// (q) => centre of mass of all bodies in the world frame (runs forward kinematics).
Vector3 centerOfMass(const Model& model, Data& data, const Eigen::VectorXd& q);
/// (q, v) => spatial momentum in the world frame: [angular momentum about the world origin; linear momentum],
/// including the fluid's impulse A_i V_i of bodies with added mass.
Force momentum(const Model& model, Data& data, const Eigen::VectorXd& q, const Eigen::VectorXd& v);

}  // namespace yardsim::dynamics
