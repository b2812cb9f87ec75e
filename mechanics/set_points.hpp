#pragma once
// The set-points in force on a mechanical system: what actors change between steps (joint
// drives, loads on bodies, winch jobs). A plain value, part of the multibody model's state.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "forces/winch.hpp"

namespace yardsim::mechanics {

// A joint driven towards a target along a ramp at a given speed: by a bounded servo, or with its
// motion prescribed (the ramp exactly; the joint is locked at the target afterwards). Joint
// coordinates: rad (revolute) or m (prismatic); speed in rad/s or m/s; times in s.
struct JointDrive {
  bool active = false;
  bool reported = false;  // the "reached" event was sent
  double start = 0.0, target = 0.0, speed = 0.0, t0 = 0.0;
  std::string actor;
  bool prescribed = false;
  // (ramp) => when a prescribed ramp ends, s
  double tEnd() const { return t0 + std::max(std::abs(target - start) / speed, 1e-9); }
};

// A winch job on a rope: paying out (or hauling in) until tEnd, s; and the rope's winch so far:
// the pieces of its unstretched length L0(t) (forces::Winch::history(), m and m/s), which the
// rope's provider mirrors.
struct WinchJob {
  bool active = false;
  double tEnd = 0.0;
  std::string actor;
  std::vector<forces::Winch::SetPoint> pieces;
};

// A force and moment an actor puts on a body: world frame, N and N m, the moment about the
// world origin together with the force (a spatial force F_W).
struct ActorLoad {
  Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
};

struct SetPoints {
  std::vector<JointDrive> drives;  // per body index (its joint)
  std::vector<ActorLoad> loads;    // per body index
  std::vector<WinchJob> winches;   // per winch (System::winches(): the ropes', then the others)
};

// (a drive request at t for the 1-dof joint of body i, now at q with velocity v: target, speed,
// the actor, servo or prescribed) => the drive in sp; the joint's velocity step when a prescribed
// ramp starts (it takes the ramp's speed at once) or a prescribed one is replaced, else 0
double startDrive(SetPoints& sp, int body, double q, double v, double target, double speed,
                  double t, const std::string& actor, bool prescribed);

// (a winch request at t on winch r (System::winches()): change of unstretched length `amount` m
// (< 0 hoists) by the drive (speed, and accel/jerk limits or none)) => the profile planned on the
// winch (replacing what was planned after t), the job in sp with its pieces; returns the time
// the job ends, s
double startWinch(SetPoints& sp, int index, forces::Winch& winch, double t, double amount,
                  const forces::WinchDrive& drive, const std::string& actor);

}  // namespace yardsim::mechanics
