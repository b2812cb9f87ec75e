#pragma once
// Rotations: exponential and logarithm of SO(3), the inverse right Jacobian, quaternions stored
// scalar first (w, x, y, z), and Euler angles for output.

#include <cmath>

#include "dynamics/spatial.hpp"

namespace yardsim::dynamics {

/// (angle, rad) => (sin angle, cos angle) in one call: glibc's sincos, whose results are the same
/// doubles as std::sin and std::cos (the same code; tests/dynamics/rotation_test.cpp checks it)
/// in about 60 % of their instructions (GCC does not merge the two calls itself: errno).
inline void sinCos(double angle, double& s, double& c) {
#if defined(__GLIBC__)
  ::sincos(angle, &s, &c);
#else
  s = std::sin(angle);
  c = std::cos(angle);
#endif
}

/// exp([w]x): the rotation by |w| about w/|w| (Rodrigues).
Matrix3 expSO3(const Vector3& w);
/// The rotation vector w with expSO3(w) = R, |w| <= pi.
Vector3 logSO3(const Matrix3& R);
/// Jr^{-1}(w): for R(t) = R0 exp([w(t)]x) with body angular velocity omega, dw/dt = Jr^{-1}(w) omega.
Matrix3 rightJacobianInverse(const Vector3& w);
/// The rotation by angle about a unit axis.
Matrix3 axisRotation(const Vector3& axis, double angle);
/// (k = 0, 1, 2; s = sin angle, c = cos angle) => R = axisRotation(unit vector k, angle), entry
/// for entry the same doubles (the general formula's terms in exact zeros and ones left out, its
/// signed zeros and its diagonal c + (1 - c) on the axis kept), without the general formula's
/// products. The axis's components must be exactly +0 and 1 (Model::jointAxis).
inline void coordinateAxisRotation(int k, double s, double c, Matrix3& R) {
  const int a = (k + 1) % 3;
  const int b = (k + 2) % 3;
  R(k, k) = c + (1.0 - c);
  R(a, a) = c;
  R(b, b) = c;
  R(a, b) = 0.0 - s;
  R(b, a) = 0.0 + s;
  R(k, a) = 0.0;
  R(a, k) = 0.0;
  R(k, b) = 0.0;
  R(b, k) = 0.0;
}

/// The rotation matrix of a unit quaternion stored (w, x, y, z) at q[0..3].
Matrix3 quaternionToMatrix(const double* q);
/// A rotation matrix => unit quaternion (w, x, y, z) with w >= 0, written to q[0..3].
void matrixToQuaternion(const Matrix3& R, double* q);

/// Euler angles (roll, pitch, yaw) of R in the z-y'-x'' intrinsic (Tait-Bryan, aerospace/marine)
/// convention: R = Rz(yaw) * Ry(pitch) * Rx(roll), with pitch in [-pi/2, pi/2] and roll, yaw in
/// (-pi, pi]. At pitch = +-pi/2 (gimbal lock) roll is set to 0 and yaw carries the rotation.
Vector3 eulerAngles(const Matrix3& R);
/// The inverse of eulerAngles: Rz(yaw) * Ry(pitch) * Rx(roll).
Matrix3 eulerToMatrix(const Vector3& rollPitchYaw);

}  // namespace yardsim::dynamics
