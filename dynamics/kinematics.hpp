#pragma once
// Forward kinematics: poses, spatial velocities and accelerations of every body, and the
// position, velocity and acceleration of any point on a body.

#include <Eigen/Core>
#include <cmath>

#include "dynamics/data.hpp"
#include "dynamics/model.hpp"
#include "dynamics/rotation.hpp"

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
/// Position in the world of the point p_B fixed on a body; needs FK(q). (Inline: the rope paths
/// call it for every attachment at every stage.)
inline Vector3 pointPosition(const Data& data, int body, const Vector3& p_B) {
  return data.X_WB[body].actPoint(p_B);
}
/// Velocity in the world frame of the point p_B fixed on a body; needs FK(q, v). (Inline.)
inline Vector3 pointVelocity(const Data& data, int body, const Vector3& p_B) {
  const Motion& v = data.V_B[body];
  return data.X_WB[body].R * (v.tail<3>() + v.head<3>().cross(p_B));
}
/// Classical acceleration in the world frame of the point p_B fixed on a body; needs FK(q, v, ddq).
Vector3 pointAcceleration(const Data& data, int body, const Vector3& p_B);
/// (roll, pitch, yaw) of the body in the world, R_WB = Rz(yaw) Ry(pitch) Rx(roll); needs FK(q).
Vector3 bodyEulerAngles(const Data& data, int body);

/// (q, body i; X_WB of its parent) => X_PB[i], X_WB[i] = X_WB[parent] X_PB[i] (and S[i] where it
/// depends on q); for a coordinate-axis joint in a translated frame (Model::jointAxis) the
/// rotation product mixes two columns (revolute) or is a copy (prismatic): equal in value to the
/// general product, whose other terms are products by exact zeros.
inline void placeBody(const Model& model, Data& data, int i, const Eigen::VectorXd& q);

/// (body i placed in the world, a 1-dof joint) => X_WB S, its motion subspace column in the world
/// frame; for a coordinate-axis joint (Model::jointAxis) read off R_WB's column k.
inline Motion worldSubspaceColumn(const Model& model, const Data& data, int i);

inline void updateJointPlacement(const Model& model, Data& data, int i, const Eigen::VectorXd& q) {
  const Joint& j = model.joints[i];
  const double* qi = q.data() + model.idxQ[i];
  const int k = model.jointAxis[i];
  if (k >= 0 && !model.placementRotated[i]) {
    // (coordinate-axis revolute or prismatic joint, translated joint frame) => the same X_PB as
    // the general path below, without its call and its axis-angle formula
    Transform& X = data.X_PB[i];
    if (j.type == JointType::Revolute) {
      double s = 0.0, c = 0.0;
      sinCos(qi[0], s, c);
      coordinateAxisRotation(k, s, c, X.R);
      X.p = model.X_PJ[i].p + Vector3::Zero();
    } else {
      X.R.setIdentity();
      X.p = model.X_PJ[i].p + j.axis * qi[0];
    }
  } else if (model.placementRotated[i]) {
    data.X_PB[i] = model.X_PJ[i] * jointTransform(j, qi);
  } else {
    const Transform X_JC = jointTransform(j, qi);
    data.X_PB[i].R = X_JC.R;
    data.X_PB[i].p = model.X_PJ[i].p + X_JC.p;
  }
  if (!j.constantSubspace()) jointMotionSubspace(j, qi, data.S[i]);
}

namespace detail {
// (angle q of body i's revolute joint about axis K of a translated joint frame; X_WB of its
// parent) => X_PB[i] as updateJointPlacement, X_WB[i]: R_WB's columns a, b mixed by (c, s), column
// K scaled by R_PB(K, K); the axis a compile-time constant
template <int K>
inline void placeRevolute(const Model& model, Data& data, int i, double q) {
  constexpr int a = (K + 1) % 3;
  constexpr int b = (K + 2) % 3;
  double s = 0.0, c = 0.0;
  sinCos(q, s, c);
  Transform& X_PB = data.X_PB[i];
  coordinateAxisRotation(K, s, c, X_PB.R);
  X_PB.p = model.X_PJ[i].p + Vector3::Zero();
  const Transform& X_WP = data.X_WB[model.parent[i]];
  Transform& X = data.X_WB[i];
  X.p = X_WP.p + X_WP.R * X_PB.p;
  const double sPos = X_PB.R(b, a), sNeg = X_PB.R(a, b);
  X.R.col(K) = X_WP.R.col(K) * X_PB.R(K, K);
  X.R.col(a) = X_WP.R.col(a) * c + X_WP.R.col(b) * sPos;
  X.R.col(b) = X_WP.R.col(a) * sNeg + X_WP.R.col(b) * c;
}
}  // namespace detail

inline void placeBody(const Model& model, Data& data, int i, const Eigen::VectorXd& q) {
  const int k = model.jointAxis[i];
  if (k >= 0 && !model.placementRotated[i]) {
    if (model.joints[i].type == JointType::Revolute) {
      const double qi = q[model.idxQ[i]];
      if (k == 0) {
        detail::placeRevolute<0>(model, data, i, qi);
      } else if (k == 1) {
        detail::placeRevolute<1>(model, data, i, qi);
      } else {
        detail::placeRevolute<2>(model, data, i, qi);
      }
      return;
    }
    // (prismatic) => R_WB = R_WP R_PB with R_PB = 1
    updateJointPlacement(model, data, i, q);
    const Transform& X_WP = data.X_WB[model.parent[i]];
    data.X_WB[i].p = X_WP.p + X_WP.R * data.X_PB[i].p;
    data.X_WB[i].R = X_WP.R;
    return;
  }
  updateJointPlacement(model, data, i, q);
  data.X_WB[i] = data.X_WB[model.parent[i]] * data.X_PB[i];
}

inline Motion worldSubspaceColumn(const Model& model, const Data& data, int i) {
  const Transform& X = data.X_WB[i];
  const int k = model.jointAxis[i];
  if (k < 0) return X.actMotion(data.S[i].col(0));
  // (S = (e_k, 0) or (0, e_k)) => X_WB S without the products by exact zeros and ones; equal to
  // the general product but for the sign of entries that are exactly zero
  Motion s;
  if (model.joints[i].type == JointType::Revolute) {
    s.head<3>() = X.R.col(k);
    s.tail<3>() = X.p.cross(s.head<3>());
  } else {
    s.head<3>().setZero();
    s.tail<3>() = X.R.col(k);
  }
  return s;
}

}  // namespace yardsim::dynamics
