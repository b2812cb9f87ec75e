#pragma once
// The benchmark's models: a planar chain of N revolute links (1 kg, 1 m rods along x, turning
// about y, gravity along -z) and a branched (binary) tree of the same links.

#include <string>

#include "dynamics/model_builder.hpp"

namespace yardsim::bench {

/// The stepping cases (RK4Step, ODEWorldStep, ODEQuickStep) restart the chain from rest every
/// kResetSteps steps of 1 ms, untimed, so that they integrate the same motion.
inline constexpr long kResetSteps = 200;

inline std::string linkName(int i) {
  std::string s("link");
  s.append(std::to_string(i));
  return s;
}

inline dynamics::Model chainModel(int n) {
  using namespace dynamics;
  ModelBuilder b;
  for (int i = 0; i < n; ++i) {
    b.addBody(linkName(i), i == 0 ? "world" : linkName(i - 1), Joint::revolute(Vector3::UnitY()),
              Transform::translation(Vector3(i == 0 ? 0.0 : 1.0, 0.0, 0.0)), rodInertia(1.0, 1.0));
  }
  return b.build();
}

/// Body i hangs from body (i - 1) / 2: a balanced binary tree of n links.
inline dynamics::Model binaryTreeModel(int n) {
  using namespace dynamics;
  ModelBuilder b;
  for (int i = 0; i < n; ++i) {
    b.addBody(linkName(i), i == 0 ? "world" : linkName((i - 1) / 2), Joint::revolute(Vector3::UnitY()),
              Transform::translation(Vector3(i == 0 ? 0.0 : 1.0, 0.0, 0.0)), rodInertia(1.0, 1.0));
  }
  return b.build();
}

/// Relative energy drift of the horizontally released double pendulum, max |E - E0| / (E0 - E_hanging),
/// over 10 s at dt = 1e-3 with yardsim's RK4 (the ODE counterpart is in ode_bench.cpp).
double yardsimDoublePendulumDrift(double dt, double duration);

}  // namespace yardsim::bench
