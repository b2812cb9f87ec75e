#include "dynamics/energy.hpp"

#include "dynamics/kinematics.hpp"

namespace yardsim::dynamics {

double kineticEnergy(const Model& m, Data& d, const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
  forwardKinematics(m, d, q, v);
  double T = 0.0;
  for (int i = 1; i < m.nbodies; ++i) T += bodyKineticEnergy(m, d, i, d.V_B[i]);
  return T;
}

double potentialEnergy(const Model& m, Data& d, const Eigen::VectorXd& q) {
  forwardKinematics(m, d, q);
  double U = 0.0;
  for (int i = 1; i < m.nbodies; ++i) U -= m.inertias[i].mass * m.gravity.dot(d.X_WB[i].actPoint(m.inertias[i].com));
  return U;
}

Vector3 centerOfMass(const Model& m, Data& d, const Eigen::VectorXd& q) {
  forwardKinematics(m, d, q);
  Vector3 c = Vector3::Zero();
  for (int i = 1; i < m.nbodies; ++i) c += m.inertias[i].mass * d.X_WB[i].actPoint(m.inertias[i].com);
  return c / m.totalMass();
}

Force momentum(const Model& m, Data& d, const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
  forwardKinematics(m, d, q, v);
  Force h = Force::Zero();
  for (int i = 1; i < m.nbodies; ++i) {
    Force h_B = m.inertias[i].apply(d.V_B[i]);
    if (d.hasAddedMass[i]) h_B += d.addedMass[i] * d.V_B[i];  // the fluid's impulse
    h += d.X_WB[i].actForce(h_B);
  }
  return h;
}

}  // namespace yardsim::dynamics
