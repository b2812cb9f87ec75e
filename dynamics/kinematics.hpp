#pragma once
// Forward kinematics: poses, spatial velocities and accelerations of every body, and the
// position, velocity and acceleration of any point on a body.

#include <Eigen/Core>

#include "dynamics/data.hpp"
#include "dynamics/model.hpp"

namespace yardsim::dynamics {

/// (q, body i) => data.X_PB[i] and, for joints whose S depends on q, data.S[i]. Used by every pass.
inline void updateJointPlacement(const Model& model, Data& data, int i, const Eigen::VectorXd& q);

/// (q) => data.X_PB, data.X_WB, data.S.
void forwardKinematics(const Model& model, Data& data, const Eigen::VectorXd& q);
/// (q, v) => also data.V_B (body frame) and data.C_B.
void forwardKinematics(const Model& model, Data& data, const Eigen::VectorXd& q, const Eigen::VectorXd& v);
/// (q, v, ddq) => also data.A_B (body frame spatial acceleration, gravity not included).
void forwardKinematics(const Model& model, Data& data, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                       const Eigen::VectorXd& ddq);

/// Spatial velocity of a body in the world frame (about the world origin); needs FK(q, v).
Motion bodyVelocityWorld(const Data& data, int body);
/// Spatial acceleration of a body in the world frame (about the world origin); needs FK(q, v, ddq).
Motion bodyAccelerationWorld(const Data& data, int body);
/// Position in the world of the point p_B fixed on a body; needs FK(q).
Vector3 pointPosition(const Data& data, int body, const Vector3& p_B);
/// Velocity in the world frame of the point p_B fixed on a body; needs FK(q, v).
Vector3 pointVelocity(const Data& data, int body, const Vector3& p_B);
/// Classical acceleration in the world frame of the point p_B fixed on a body; needs FK(q, v, ddq).
Vector3 pointAcceleration(const Data& data, int body, const Vector3& p_B);
/// (roll, pitch, yaw) of the body in the world, R_WB = Rz(yaw) Ry(pitch) Rx(roll); needs FK(q).
Vector3 bodyEulerAngles(const Data& data, int body);

inline void updateJointPlacement(const Model& model, Data& data, int i, const Eigen::VectorXd& q) {
  const Joint& j = model.joints[i];
  const double* qi = q.data() + model.idxQ[i];
  if (model.placementRotated[i]) {
    data.X_PB[i] = model.X_PJ[i] * jointTransform(j, qi);
  } else {
    const Transform X_JC = jointTransform(j, qi);
    data.X_PB[i].R = X_JC.R;
    data.X_PB[i].p = model.X_PJ[i].p + X_JC.p;
  }
  if (!j.constantSubspace()) jointMotionSubspace(j, qi, data.S[i]);
}

}  // namespace yardsim::dynamics
