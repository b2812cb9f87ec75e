#include "dynamics/joint.hpp"

#include <cmath>

#include "dynamics/rotation.hpp"

namespace yardsim::dynamics {

namespace {
Matrix3 planarRotation(double angle) { return axisRotation(Vector3::UnitZ(), angle); }
}  // namespace

int Joint::nq() const {
  switch (type) {
    case JointType::Fixed: return 0;
    case JointType::Revolute:
    case JointType::Prismatic: return 1;
    case JointType::Cylindrical:
    case JointType::Universal: return 2;
    case JointType::Planar:
    case JointType::Translation: return 3;
    case JointType::Spherical: return 4;
    case JointType::Free: return 7;
  }
  return 0;
}

int Joint::nv() const {
  switch (type) {
    case JointType::Fixed: return 0;
    case JointType::Revolute:
    case JointType::Prismatic: return 1;
    case JointType::Cylindrical:
    case JointType::Universal: return 2;
    case JointType::Planar:
    case JointType::Translation:
    case JointType::Spherical: return 3;
    case JointType::Free: return 6;
  }
  return 0;
}

std::string_view jointTypeName(JointType type) {
  switch (type) {
    case JointType::Fixed: return "fixed";
    case JointType::Revolute: return "revolute";
    case JointType::Prismatic: return "prismatic";
    case JointType::Cylindrical: return "cylindrical";
    case JointType::Universal: return "universal";
    case JointType::Spherical: return "spherical";
    case JointType::Planar: return "planar";
    case JointType::Free: return "free";
    case JointType::Translation: return "translation";
  }
  return "?";
}

Transform jointTransform(const Joint& j, const double* q) {
  switch (j.type) {
    case JointType::Fixed: return {};
    case JointType::Revolute: return {axisRotation(j.axis, q[0]), Vector3::Zero()};
    case JointType::Prismatic: return {Matrix3::Identity(), j.axis * q[0]};
    case JointType::Cylindrical: return {axisRotation(j.axis, q[0]), j.axis * q[1]};
    case JointType::Universal: return {axisRotation(j.axis, q[0]) * axisRotation(j.axis2, q[1]), Vector3::Zero()};
    case JointType::Spherical: return {quaternionToMatrix(q), Vector3::Zero()};
    case JointType::Planar: return {planarRotation(q[2]), Vector3(q[0], q[1], 0.0)};
    case JointType::Free: return {quaternionToMatrix(q + 3), Vector3(q[0], q[1], q[2])};
    case JointType::Translation: return {Matrix3::Identity(), Vector3(q[0], q[1], q[2])};
  }
  return {};
}

void jointMotionSubspace(const Joint& j, const double* q, MotionSubspace& S) {
  S.setZero(6, j.nv());
  switch (j.type) {
    case JointType::Fixed: break;
    case JointType::Revolute: S.block<3, 1>(0, 0) = j.axis; break;
    case JointType::Prismatic: S.block<3, 1>(3, 0) = j.axis; break;
    case JointType::Cylindrical:
      S.block<3, 1>(0, 0) = j.axis;
      S.block<3, 1>(3, 1) = j.axis;
      break;
    case JointType::Universal:
      // (q2) => omega_C = R2^T a1 q1dot + a2 q2dot
      S.block<3, 1>(0, 0) = axisRotation(j.axis2, q[1]).transpose() * j.axis;
      S.block<3, 1>(0, 1) = j.axis2;
      break;
    case JointType::Spherical: S.topLeftCorner<3, 3>().setIdentity(); break;
    case JointType::Planar: {
      // (theta) => v_C = Rz^T (xdot, ydot, 0), omega_C = thetadot e_z
      const Matrix3 Rt = planarRotation(q[2]).transpose();
      S.block<3, 2>(3, 0) = Rt.leftCols<2>();
      S(2, 2) = 1.0;
      break;
    }
    case JointType::Free: S.setIdentity(); break;
    case JointType::Translation: S.bottomLeftCorner<3, 3>().setIdentity(); break;
  }
}

Motion jointBias(const Joint& j, const double* q, const double* v) {
  Motion c = Motion::Zero();
  if (j.type == JointType::Universal) {
    // (q2, v) => d/dt(R2^T a1) q1dot = -q2dot a2 x (R2^T a1) q1dot
    const Vector3 s1 = axisRotation(j.axis2, q[1]).transpose() * j.axis;
    c.head<3>() = -v[0] * v[1] * j.axis2.cross(s1);
  } else if (j.type == JointType::Planar) {
    // (theta, v) => d/dt(Rz^T) (xdot, ydot, 0) = -thetadot e_z x Rz^T (xdot, ydot, 0)
    const Vector3 vC = planarRotation(q[2]).transpose() * Vector3(v[0], v[1], 0.0);
    c.tail<3>() = -v[2] * Vector3::UnitZ().cross(vC);
  }
  return c;
}

void jointIntegrate(const Joint& j, const double* q, const double* v, double dt, double* qOut) {
  switch (j.type) {
    case JointType::Spherical: {
      const Matrix3 R = quaternionToMatrix(q) * expSO3(Vector3(v[0], v[1], v[2]) * dt);
      matrixToQuaternion(R, qOut);
      break;
    }
    case JointType::Free: {
      const Matrix3 R0 = quaternionToMatrix(q + 3);
      const Vector3 p = Vector3(q[0], q[1], q[2]) + R0 * Vector3(v[3], v[4], v[5]) * dt;
      const Matrix3 R = R0 * expSO3(Vector3(v[0], v[1], v[2]) * dt);
      qOut[0] = p.x();
      qOut[1] = p.y();
      qOut[2] = p.z();
      matrixToQuaternion(R, qOut + 3);
      break;
    }
    default:
      for (int k = 0; k < j.nq(); ++k) qOut[k] = q[k] + v[k] * dt;
  }
}

void jointDifference(const Joint& j, const double* q0, const double* q1, double* d) {
  switch (j.type) {
    case JointType::Spherical: {
      const Vector3 w = logSO3(quaternionToMatrix(q0).transpose() * quaternionToMatrix(q1));
      for (int k = 0; k < 3; ++k) d[k] = w[k];
      break;
    }
    case JointType::Free: {
      const Matrix3 R0 = quaternionToMatrix(q0 + 3);
      const Vector3 w = logSO3(R0.transpose() * quaternionToMatrix(q1 + 3));
      const Vector3 dp = R0.transpose() * (Vector3(q1[0], q1[1], q1[2]) - Vector3(q0[0], q0[1], q0[2]));
      for (int k = 0; k < 3; ++k) {
        d[k] = w[k];
        d[3 + k] = dp[k];
      }
      break;
    }
    default:
      for (int k = 0; k < j.nq(); ++k) d[k] = q1[k] - q0[k];
  }
}

void jointChartRate(const Joint& j, const double* theta, const double* v, double* thetaDot) {
  switch (j.type) {
    case JointType::Spherical: {
      const Vector3 r = rightJacobianInverse(Vector3(theta[0], theta[1], theta[2])) * Vector3(v[0], v[1], v[2]);
      for (int k = 0; k < 3; ++k) thetaDot[k] = r[k];
      break;
    }
    case JointType::Free: {
      // q = (p0 + R0 theta_p, R0 exp(theta_w)): dp/dt = R0 exp(theta_w) v_lin
      const Vector3 tw(theta[0], theta[1], theta[2]);
      const Vector3 r = rightJacobianInverse(tw) * Vector3(v[0], v[1], v[2]);
      const Vector3 l = expSO3(tw) * Vector3(v[3], v[4], v[5]);
      for (int k = 0; k < 3; ++k) {
        thetaDot[k] = r[k];
        thetaDot[3 + k] = l[k];
      }
      break;
    }
    default:
      for (int k = 0; k < j.nv(); ++k) thetaDot[k] = v[k];
  }
}

void jointNeutral(const Joint& j, double* q) {
  for (int k = 0; k < j.nq(); ++k) q[k] = 0.0;
  if (j.type == JointType::Spherical) q[0] = 1.0;
  if (j.type == JointType::Free) q[3] = 1.0;
}

void jointNormalize(const Joint& j, double* q) {
  double* quat = j.type == JointType::Spherical ? q : (j.type == JointType::Free ? q + 3 : nullptr);
  if (quat == nullptr) return;
  const double n = std::sqrt(quat[0] * quat[0] + quat[1] * quat[1] + quat[2] * quat[2] + quat[3] * quat[3]);
  for (int k = 0; k < 4; ++k) quat[k] /= n;
}

}  // namespace yardsim::dynamics
