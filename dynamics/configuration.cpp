#include "dynamics/configuration.hpp"

namespace yardsim::dynamics {

void integrate(const Model& m, const Eigen::VectorXd& q, const Eigen::VectorXd& v, double dt, Eigen::VectorXd& qOut) {
  if (m.euclidean) {
    qOut = q + dt * v;
    return;
  }
  for (int i = 1; i < m.nbodies; ++i) {
    jointIntegrate(m.joints[i], q.data() + m.idxQ[i], v.data() + m.idxV[i], dt, qOut.data() + m.idxQ[i]);
  }
}

void difference(const Model& m, const Eigen::VectorXd& q0, const Eigen::VectorXd& q1, Eigen::VectorXd& d) {
  if (m.euclidean) {
    d = q1 - q0;
    return;
  }
  for (int i = 1; i < m.nbodies; ++i) {
    jointDifference(m.joints[i], q0.data() + m.idxQ[i], q1.data() + m.idxQ[i], d.data() + m.idxV[i]);
  }
}

void chartRate(const Model& m, const Eigen::VectorXd& theta, const Eigen::VectorXd& v, Eigen::VectorXd& thetaDot) {
  if (m.euclidean) {
    thetaDot = v;
    return;
  }
  for (int i = 1; i < m.nbodies; ++i) {
    jointChartRate(m.joints[i], theta.data() + m.idxV[i], v.data() + m.idxV[i], thetaDot.data() + m.idxV[i]);
  }
}

Eigen::VectorXd neutralConfiguration(const Model& m) {
  Eigen::VectorXd q(m.nq);
  for (int i = 1; i < m.nbodies; ++i) jointNeutral(m.joints[i], q.data() + m.idxQ[i]);
  return q;
}

void normalizeConfiguration(const Model& m, Eigen::VectorXd& q) {
  for (int i = 1; i < m.nbodies; ++i) jointNormalize(m.joints[i], q.data() + m.idxQ[i]);
}

Eigen::VectorXd randomConfiguration(const Model& m, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::normal_distribution<double> n(0.0, 1.0);
  Eigen::VectorXd q(m.nq);
  for (int i = 1; i < m.nbodies; ++i) {
    double* qi = q.data() + m.idxQ[i];
    const JointType t = m.joints[i].type;
    for (int k = 0; k < m.jointNq[i]; ++k) qi[k] = u(rng);
    double* quat = t == JointType::Spherical ? qi : (t == JointType::Free ? qi + 3 : nullptr);
    if (quat != nullptr) {
      for (int k = 0; k < 4; ++k) quat[k] = n(rng);
      jointNormalize(m.joints[i], qi);
    }
  }
  return q;
}

}  // namespace yardsim::dynamics
