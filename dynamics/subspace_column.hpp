#pragma once
// The world-frame motion subspace column of a 1-dof joint about or along a coordinate axis of a
// translated joint frame, on plain doubles (the values of kinematics.hpp's worldSubspaceColumn,
// which ABA and CRBA write into S_W entry by entry before they read it as SSE2 pairs).

namespace yardsim::dynamics {

/// (revolute or prismatic; w = R_WB's column K, the joint axis in world axes, unitless; p = the
/// body origin in the world frame, m) => s = (w, p x w) for a revolute joint, (0, w) for a
/// prismatic one, as [angular; linear] (the same doubles as worldSubspaceColumn)
inline void coordinateAxisSubspace(bool revolute, const double* w, const double* p, double* s) {
  if (revolute) {
    s[0] = w[0];
    s[1] = w[1];
    s[2] = w[2];
    s[3] = p[1] * w[2] - p[2] * w[1];
    s[4] = p[2] * w[0] - p[0] * w[2];
    s[5] = p[0] * w[1] - p[1] * w[0];
  } else {
    s[0] = 0.0;
    s[1] = 0.0;
    s[2] = 0.0;
    s[3] = w[0];
    s[4] = w[1];
    s[5] = w[2];
  }
}

}  // namespace yardsim::dynamics
