#include "dynamics/rotation.hpp"

#include <algorithm>
#include <cmath>

namespace yardsim::dynamics {

Matrix3 expSO3(const Vector3& w) {
  const double t2 = w.squaredNorm();
  const double t = std::sqrt(t2);
  double a = 0.0;  // sin t / t
  double b = 0.0;  // (1 - cos t) / t^2
  if (t < 1e-4) {
    a = 1.0 - t2 / 6.0;
    b = 0.5 - t2 / 24.0;
  } else {
    a = std::sin(t) / t;
    b = (1.0 - std::cos(t)) / t2;
  }
  const Matrix3 W = skew(w);
  return Matrix3::Identity() + a * W + b * W * W;
}

Vector3 logSO3(const Matrix3& R) {
  // (R) => (rotation vector), robust near 0 and pi.
  const Eigen::AngleAxisd aa(R);
  return aa.angle() * aa.axis();
}

Matrix3 rightJacobianInverse(const Vector3& w) {
  const double t2 = w.squaredNorm();
  const double t = std::sqrt(t2);
  double c = 0.0;  // 1/t^2 - (1 + cos t) / (2 t sin t)
  if (t < 1e-3) {
    c = 1.0 / 12.0 + t2 / 720.0;
  } else {
    c = 1.0 / t2 - (1.0 + std::cos(t)) / (2.0 * t * std::sin(t));
  }
  const Matrix3 W = skew(w);
  return Matrix3::Identity() + 0.5 * W + c * W * W;
}

Matrix3 axisRotation(const Vector3& axis, double angle) {
  double s = 0.0, c = 0.0;
  sinCos(angle, s, c);
  const double x = axis.x(), y = axis.y(), z = axis.z();
  const double k = 1.0 - c;
  Matrix3 R;
  R << c + x * x * k, x * y * k - z * s, x * z * k + y * s,  //
      y * x * k + z * s, c + y * y * k, y * z * k - x * s,   //
      z * x * k - y * s, z * y * k + x * s, c + z * z * k;
  return R;
}

Matrix3 quaternionToMatrix(const double* q) {
  const Eigen::Quaterniond quat(q[0], q[1], q[2], q[3]);
  return quat.toRotationMatrix();
}

void matrixToQuaternion(const Matrix3& R, double* q) {
  Eigen::Quaterniond quat(R);
  quat.normalize();
  if (quat.w() < 0.0) quat.coeffs() = -quat.coeffs();
  q[0] = quat.w();
  q[1] = quat.x();
  q[2] = quat.y();
  q[3] = quat.z();
}

Vector3 eulerAngles(const Matrix3& R) {
  // (R = Rz(yaw) Ry(pitch) Rx(roll)) => (roll, pitch, yaw); R(2,0) = -sin(pitch).
  const double sp = std::clamp(-R(2, 0), -1.0, 1.0);
  const double pitch = std::asin(sp);
  double roll = 0.0;
  double yaw = 0.0;
  if (std::abs(sp) < 1.0 - 1e-12) {
    roll = std::atan2(R(2, 1), R(2, 2));
    yaw = std::atan2(R(1, 0), R(0, 0));
  } else {
    // gimbal lock: only yaw -+ roll is defined; put it all in yaw.
    yaw = std::atan2(-R(0, 1), R(1, 1));
  }
  return {roll, pitch, yaw};
}

Matrix3 eulerToMatrix(const Vector3& rpy) {
  return (Eigen::AngleAxisd(rpy.z(), Vector3::UnitZ()) * Eigen::AngleAxisd(rpy.y(), Vector3::UnitY()) *
          Eigen::AngleAxisd(rpy.x(), Vector3::UnitX()))
      .toRotationMatrix();
}

}  // namespace yardsim::dynamics
