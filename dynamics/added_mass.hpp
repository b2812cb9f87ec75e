#pragma once
// A hydrodynamic added-mass matrix as the kernel wants it. Naval architecture (and the panel
// solver, forces/hydro/added_mass.hpp) orders the six modes surge, sway, heave, roll, pitch, yaw
// (translations first) about a reference point R; the kernel's spatial matrices are ordered
// [angular; linear] about the body origin. Both are in the body frame.
#include "dynamics/spatial.hpp"

namespace yardsim::dynamics {

/// (A in the naval order about R, p_BR: R in the body frame) => the same matrix ordered
/// [angular; linear] about the body origin, for ModelBuilder::setAddedMass.
inline Matrix6 addedMassAboutOrigin(const Matrix6& A_naval_R, const Vector3& p_BR) {
  // (naval order) => [angular; linear] about R, then shifted to the origin: A_B = X_BR^* A_R X_BR^-1
  Matrix6 A_R;
  A_R.topLeftCorner<3, 3>() = A_naval_R.bottomRightCorner<3, 3>();
  A_R.topRightCorner<3, 3>() = A_naval_R.bottomLeftCorner<3, 3>();
  A_R.bottomLeftCorner<3, 3>() = A_naval_R.topRightCorner<3, 3>();
  A_R.bottomRightCorner<3, 3>() = A_naval_R.topLeftCorner<3, 3>();
  return actInertia(Transform::translation(p_BR), A_R);
}

}  // namespace yardsim::dynamics
