#pragma once
// Joints: the motion a child body may have relative to its joint frame on the parent.
// q and v of one joint are slices of the model's configuration and velocity vectors; nq != nv
// where a quaternion is used (spherical, free). Velocities are expressed in the child frame for
// spherical and free joints (body angular velocity; free: also the body-frame velocity of the
// child origin); for the others v = dq/dt.

#include <string_view>

#include "dynamics/spatial.hpp"

namespace yardsim::dynamics {

enum class JointType { Fixed, Revolute, Prismatic, Cylindrical, Universal, Spherical, Planar, Free, Translation };

/// The motion subspace S (6 x nv, child frame) of one joint; at most 6 columns, no heap.
using MotionSubspace = Eigen::Matrix<double, 6, Eigen::Dynamic, Eigen::ColMajor, 6, 6>;

struct Joint {
  JointType type = JointType::Fixed;
  Vector3 axis = Vector3::UnitZ();   ///< revolute, prismatic, cylindrical: the axis; universal: first axis
  Vector3 axis2 = Vector3::UnitY();  ///< universal: second axis (in the frame after the first rotation)

  static Joint fixed() { return {JointType::Fixed, Vector3::UnitZ(), Vector3::UnitY()}; }
  /// Rotation about a unit axis of the joint frame; q = angle.
  static Joint revolute(const Vector3& axis = Vector3::UnitZ()) { return {JointType::Revolute, axis, Vector3::UnitY()}; }
  /// Translation along a unit axis; q = displacement.
  static Joint prismatic(const Vector3& axis = Vector3::UnitZ()) { return {JointType::Prismatic, axis, Vector3::UnitY()}; }
  /// Rotation about and translation along one axis; q = (angle, displacement).
  static Joint cylindrical(const Vector3& axis = Vector3::UnitZ()) { return {JointType::Cylindrical, axis, Vector3::UnitY()}; }
  /// Rotation about axis1 then about axis2 (orthogonal); q = (angle1, angle2).
  static Joint universal(const Vector3& axis1 = Vector3::UnitX(), const Vector3& axis2 = Vector3::UnitY()) {
    return {JointType::Universal, axis1, axis2};
  }
  /// Ball joint; q = unit quaternion (w, x, y, z) of R_JC, v = angular velocity in the child frame.
  static Joint spherical() { return {JointType::Spherical, Vector3::UnitZ(), Vector3::UnitY()}; }
  /// Motion in the joint's x-y plane; q = (x, y, angle about z), v = dq/dt.
  static Joint planar() { return {JointType::Planar, Vector3::UnitZ(), Vector3::UnitY()}; }
  /// 6-DOF floating joint; q = (position of the child origin in the joint frame, quaternion (w, x, y, z)),
  /// v = (angular velocity, velocity of the child origin), both in the child frame.
  static Joint free() { return {JointType::Free, Vector3::UnitZ(), Vector3::UnitY()}; }
  /// 3-DOF translation without rotation (a point mass: a lumped line's node); q = position of the
  /// child origin in the joint frame, v = dq/dt (child frame = joint frame orientation).
  static Joint translation() { return {JointType::Translation, Vector3::UnitZ(), Vector3::UnitY()}; }

  int nq() const;
  int nv() const;
  /// True when S does not depend on q (all but universal and planar).
  bool constantSubspace() const { return type != JointType::Universal && type != JointType::Planar; }
};

std::string_view jointTypeName(JointType type);

/// (joint, q) => X_JC, pose of the child frame in the joint frame.
Transform jointTransform(const Joint& joint, const double* q);
/// (joint, q) => S, motion subspace in the child frame (resized to 6 x nv).
void jointMotionSubspace(const Joint& joint, const double* q, MotionSubspace& S);
/// (joint, q, v) => c_J = (apparent d/dt of S) v in the child frame; zero for constant S.
Motion jointBias(const Joint& joint, const double* q, const double* v);

/// (joint, q, v, dt) => q_out = q (+) v dt. For spherical: R exp(w dt); free: p + R v dt, R exp(w dt).
void jointIntegrate(const Joint& joint, const double* q, const double* v, double dt, double* qOut);
/// (joint, q0, q1) => d with jointIntegrate(q0, d, 1) = q1.
void jointDifference(const Joint& joint, const double* q0, const double* q1, double* d);
/// (joint, theta, v) => dtheta/dt for q(t) = q0 (+) theta(t) moving with velocity v.
void jointChartRate(const Joint& joint, const double* theta, const double* v, double* thetaDot);
/// (joint) => q at rest (zero angles, identity quaternion).
void jointNeutral(const Joint& joint, double* q);
/// (joint, q) => q with its quaternion normalised.
void jointNormalize(const Joint& joint, double* q);

}  // namespace yardsim::dynamics
