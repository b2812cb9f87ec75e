#pragma once
// Spatial algebra (Featherstone, Rigid Body Dynamics Algorithms, ch. 2) on Eigen fixed-size types.
// A spatial vector is ordered [angular; linear]: a motion is (omega, v_O), the angular velocity
// and the velocity of the body-fixed point at the frame origin; a force is (n_O, f), the moment
// about the frame origin and the resultant force.

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace yardsim::dynamics {

using Vector3 = Eigen::Vector3d;
using Matrix3 = Eigen::Matrix3d;
using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Motion = Vector6;  ///< spatial motion vector [omega; v_O]
using Force = Vector6;   ///< spatial force vector [n_O; f]

/// [a]x, the matrix of the cross product a x (.).
inline Matrix3 skew(const Vector3& a) {
  Matrix3 m;
  m << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return m;
}

/// v x m, the spatial cross product of two motions (Featherstone crm).
inline Motion crossMotion(const Motion& v, const Motion& m) {
  Motion r;
  r.head<3>() = v.head<3>().cross(m.head<3>());
  r.tail<3>() = v.head<3>().cross(m.tail<3>()) + v.tail<3>().cross(m.head<3>());
  return r;
}

/// v x* f, the spatial cross product of a motion with a force (Featherstone crf).
inline Force crossForce(const Motion& v, const Force& f) {
  Force r;
  r.head<3>() = v.head<3>().cross(f.head<3>()) + v.tail<3>().cross(f.tail<3>());
  r.tail<3>() = v.head<3>().cross(f.tail<3>());
  return r;
}

/// A rigid transform X_AB: the pose of frame B in frame A (rotation R_AB, origin p_AB of B in A).
/// As a Plücker transform it maps spatial vectors expressed in B to the same vectors in A.
struct Transform {
  Matrix3 R = Matrix3::Identity();  ///< R_AB: columns are B's axes in A
  Vector3 p = Vector3::Zero();      ///< p_AB: origin of B in A

  static Transform identity() { return {}; }
  static Transform translation(const Vector3& t) { return {Matrix3::Identity(), t}; }
  static Transform rotation(const Matrix3& r) { return {r, Vector3::Zero()}; }

  /// X_AC = X_AB * X_BC.
  Transform operator*(const Transform& X_BC) const { return {R * X_BC.R, p + R * X_BC.p}; }
  /// X_BA.
  Transform inverse() const { return {R.transpose(), -(R.transpose() * p)}; }
  /// A point given in B, in A.
  Vector3 actPoint(const Vector3& p_B) const { return R * p_B + p; }
  /// A point given in A, in B.
  Vector3 invActPoint(const Vector3& p_A) const { return R.transpose() * (p_A - p); }

  /// Motion in B => motion in A.
  Motion actMotion(const Motion& m_B) const {
    Motion r;
    r.head<3>() = R * m_B.head<3>();
    r.tail<3>() = R * m_B.tail<3>() + p.cross(r.head<3>());
    return r;
  }
  /// Motion in A => motion in B.
  Motion invActMotion(const Motion& m_A) const {
    Motion r;
    r.head<3>() = R.transpose() * m_A.head<3>();
    r.tail<3>() = R.transpose() * (m_A.tail<3>() - p.cross(m_A.head<3>()));
    return r;
  }
  /// Force in B => force in A.
  Force actForce(const Force& f_B) const {
    Force r;
    r.tail<3>() = R * f_B.tail<3>();
    r.head<3>() = R * f_B.head<3>() + p.cross(r.tail<3>());
    return r;
  }
  /// Force in A => force in B.
  Force invActForce(const Force& f_A) const {
    Force r;
    r.tail<3>() = R.transpose() * f_A.tail<3>();
    r.head<3>() = R.transpose() * (f_A.head<3>() - p.cross(f_A.tail<3>()));
    return r;
  }
  /// The 6x6 motion transform matrix (B => A).
  Matrix6 motionMatrix() const {
    Matrix6 X;
    X.topLeftCorner<3, 3>() = R;
    X.topRightCorner<3, 3>().setZero();
    X.bottomLeftCorner<3, 3>() = skew(p) * R;
    X.bottomRightCorner<3, 3>() = R;
    return X;
  }
};

/// A 6x6 symmetric inertia-like matrix in B (blocks [[A, B], [B^T, C]]) => the same in A:
/// I_A = X_AB^* I_B X_AB^{-1}.
inline Matrix6 actInertia(const Transform& X_AB, const Matrix6& I_B) {
  const Matrix3& R = X_AB.R;
  const Matrix3 Ar = R * I_B.topLeftCorner<3, 3>() * R.transpose();
  const Matrix3 Br = R * I_B.topRightCorner<3, 3>() * R.transpose();
  const Matrix3 Cr = R * I_B.bottomRightCorner<3, 3>() * R.transpose();
  const Matrix3 px = skew(X_AB.p);
  const Matrix3 pxC = px * Cr;
  const Matrix3 Bn = Br + pxC;
  const Matrix3 BpxT = Br * px;
  Matrix6 I_A;
  I_A.topLeftCorner<3, 3>() = Ar + px * Br.transpose() - BpxT - pxC * px;
  I_A.topRightCorner<3, 3>() = Bn;
  I_A.bottomLeftCorner<3, 3>() = Bn.transpose();
  I_A.bottomRightCorner<3, 3>() = Cr;
  return I_A;
}

/// The spatial inertia of a rigid body: mass, centre of mass c and rotational inertia about the
/// centre of mass, all in the body frame.
struct SpatialInertia {
  double mass = 0.0;
  Vector3 com = Vector3::Zero();
  Matrix3 inertiaCom = Matrix3::Zero();

  /// The 6x6 matrix about the frame origin.
  Matrix6 matrix() const {
    const Matrix3 cx = skew(com);
    Matrix6 I;
    I.topLeftCorner<3, 3>() = inertiaCom - mass * cx * cx;
    I.topRightCorner<3, 3>() = mass * cx;
    I.bottomLeftCorner<3, 3>() = -mass * cx;
    I.bottomRightCorner<3, 3>() = mass * Matrix3::Identity();
    return I;
  }
  /// The 6x6 matrix of this inertia (given in frame B) expressed in frame A, X_AB being the pose of
  /// B in A; cheaper than actInertia(X_AB, matrix()). kDiagonal: inertiaCom is diagonal (the
  /// same values, R Ic formed by scaling R's columns).
  template <bool kDiagonal = false>
  Matrix6 matrixIn(const Transform& X_AB) const {
    const Vector3 c = X_AB.R * com + X_AB.p;
    Matrix3 RIc;
    if constexpr (kDiagonal) {
      RIc = X_AB.R * inertiaCom.diagonal().asDiagonal();
    } else {
      RIc = X_AB.R * inertiaCom;
    }
    const Matrix3 Ic = RIc * X_AB.R.transpose();
    const Matrix3 cx = skew(c);
    Matrix6 I;
    I.topLeftCorner<3, 3>() = Ic + mass * (c.squaredNorm() * Matrix3::Identity() - c * c.transpose());
    I.topRightCorner<3, 3>() = mass * cx;
    I.bottomLeftCorner<3, 3>() = -mass * cx;
    I.bottomRightCorner<3, 3>() = mass * Matrix3::Identity();
    return I;
  }
  /// I * v, the momentum of the body moving with v.
  Force apply(const Motion& v) const {
    Force h;
    h.tail<3>() = mass * (v.tail<3>() - com.cross(v.head<3>()));
    h.head<3>() = inertiaCom * v.head<3>() + com.cross(h.tail<3>());
    return h;
  }
};

}  // namespace yardsim::dynamics
