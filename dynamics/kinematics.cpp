#include "dynamics/kinematics.hpp"

#include "dynamics/checks.hpp"
#include "dynamics/rotation.hpp"

namespace yardsim::dynamics {

void forwardKinematics(const Model& m, Data& d, const Eigen::VectorXd& q) {
  YARDSIM_DYNAMICS_CHECK(m, d, q, nullptr, nullptr, "forwardKinematics");
  // (q) => X_PB, X_WB
  for (int i = 1; i < m.nbodies; ++i) {
    placeBody(m, d, i, q);
  }
}

void forwardKinematics(const Model& m, Data& d, const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
  YARDSIM_DYNAMICS_CHECK(m, d, q, &v, nullptr, "forwardKinematics");
  // (q, v) => X_PB, X_WB, V = X^-1 V_parent + S v_i, C = c_J + V x S v_i
  for (int i = 1; i < m.nbodies; ++i) {
    placeBody(m, d, i, q);
    const int p = m.parent[i];
    const auto vi = v.segment(m.idxV[i], m.jointNv[i]);
    const Motion vJ = d.S[i] * vi;
    d.V_B[i] = d.X_PB[i].invActMotion(d.V_B[p]) + vJ;
    d.C_B[i] = jointBias(m.joints[i], q.data() + m.idxQ[i], v.data() + m.idxV[i]) + crossMotion(d.V_B[i], vJ);
  }
}

void forwardKinematics(const Model& m, Data& d, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                       const Eigen::VectorXd& ddq) {
  // (q, v, ddq) => ..., A = X^-1 A_parent + S ddq_i + C
  forwardKinematics(m, d, q, v);
  d.A_B[0].setZero();  // RNEA and ABA leave -g here
  for (int i = 1; i < m.nbodies; ++i) {
    const int p = m.parent[i];
    d.A_B[i] = d.X_PB[i].invActMotion(d.A_B[p]) + d.S[i] * ddq.segment(m.idxV[i], m.jointNv[i]) + d.C_B[i];
  }
}

Motion bodyVelocityWorld(const Data& d, int body) { return d.X_WB[body].actMotion(d.V_B[body]); }

Motion bodyAccelerationWorld(const Data& d, int body) { return d.X_WB[body].actMotion(d.A_B[body]); }

Vector3 pointAcceleration(const Data& d, int body, const Vector3& p_B) {
  // (V, A, p) => a_O + alpha x p + w x (v_O + w x p), body frame, then rotated to the world
  const Motion& v = d.V_B[body];
  const Motion& a = d.A_B[body];
  const Vector3 pdot = v.tail<3>() + v.head<3>().cross(p_B);
  return d.X_WB[body].R * (a.tail<3>() + a.head<3>().cross(p_B) + v.head<3>().cross(pdot));
}

Vector3 bodyEulerAngles(const Data& d, int body) { return eulerAngles(d.X_WB[body].R); }

}  // namespace yardsim::dynamics
