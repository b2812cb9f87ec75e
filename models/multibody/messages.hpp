#pragma once
// The discrete messages between actors and a multibody model (DESIGN.md: the DEVS graph
// carries set-points and state events, never the continuous state).
#include <ostream>
#include <string>

namespace yardsim::models {

// A set-point for one mechanical element, applied by the multibody model at the exact time it
// arrives.
struct SetPoint {
  enum class Kind { JointTarget, WinchPayout, ActorLoad, WinchStop };
  Kind kind = Kind::JointTarget;
  std::string element;  // joint, rope or body name inside the multibody model
  std::string actor;    // path of the actor that sent it (echoed in the events it causes)
  // JointTarget: drive the joint to `target` (rad or m) at `speed` (rad/s or m/s, > 0)
  // WinchPayout: change the rope's unstretched length by `amount` (m, < 0 hoists) at `speed`
  // WinchStop: the rope's winch stops at once (what was planned after now is dropped)
  double target = 0.0, speed = 0.0, amount = 0.0;
  // WinchPayout: the drive's acceleration (m/s^2) and jerk (m/s^3) limits; 0: none (the speed
  // steps at once, or ramps as a trapezoid)
  double accel = 0.0, jerk = 0.0;
  // JointTarget: true: the joint's motion is prescribed (the ramp exactly, whatever it takes);
  // false: a bounded servo follows the ramp
  bool prescribed = false;
  // ActorLoad: force (N) and moment (N m) in the world frame at the body origin (zero: release)
  double force[3] = {0, 0, 0}, moment[3] = {0, 0, 0};
};

// What a multibody model reports: an element reached what a set-point asked for, or a watched
// quantity crossed its threshold.
struct MechanicsEvent {
  std::string element;
  std::string actor;  // the actor whose set-point it answers ("" for watches)
  std::string what;   // "reached", "done", "over_mbl", "taut", "slack" (a rope's transitions),
                      // a provider's ("clearance_below", "touched", "contact", "release")
  double value = 0.0;
  std::string detail = {};  // provider events: the pair and witness points ("" for none)
};

std::ostream& operator<<(std::ostream& os, const SetPoint& s);
std::ostream& operator<<(std::ostream& os, const MechanicsEvent& e);

}  // namespace yardsim::models
