#include "mechanics/set_points.hpp"

namespace yardsim::mechanics {

double startDrive(SetPoints& sp, int body, double q, double v, double target, double speed,
                  double t, const std::string& actor, bool prescribed) {
  JointDrive& d = sp.drives[static_cast<std::size_t>(body)];
  d = JointDrive{true, false, q, target, std::abs(speed), t, actor, prescribed};
  // (ramp start) => the joint takes the ramp's speed at once (servo: keeps its own)
  if (!prescribed) return 0.0;  // a servo keeps its own velocity; a replaced ramp stops its impulse
  if (target == q) return -v;
  return (target >= q ? 1.0 : -1.0) * std::abs(speed) - v;
}

double startWinch(SetPoints& sp, int index, forces::Winch& winch, double t, double amount,
                  const forces::WinchDrive& drive, const std::string& actor) {
  WinchJob& job = sp.winches[static_cast<std::size_t>(index)];
  winch.dropPlannedAfter(t);
  job.active = true;
  job.tEnd = winch.setPayoutProfile(t, forces::winchProfile(amount, drive));
  job.actor = actor;
  job.pieces = winch.history();
  return job.tEnd;
}

}  // namespace yardsim::mechanics
