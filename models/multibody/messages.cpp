#include "models/multibody/messages.hpp"

namespace yardsim::models {

std::ostream& operator<<(std::ostream& os, const SetPoint& s) {
  switch (s.kind) {
    case SetPoint::Kind::JointTarget:
      return os << s.element << " -> " << s.target << " at " << s.speed;
    case SetPoint::Kind::WinchPayout:
      os << s.element << " payout " << s.amount << " at " << s.speed;
      if (s.accel > 0) os << " accel " << s.accel;
      if (s.jerk > 0) os << " jerk " << s.jerk;
      return os;
    case SetPoint::Kind::WinchStop:
      return os << s.element << " stop";
    case SetPoint::Kind::ActorLoad:
      return os << s.element << " load (" << s.force[0] << "," << s.force[1] << "," << s.force[2]
                << ")";
  }
  return os;
}

std::ostream& operator<<(std::ostream& os, const MechanicsEvent& e) {
  os << e.element << " " << e.what << " " << e.value << (e.actor.empty() ? "" : " for " + e.actor);
  return os << (e.detail.empty() ? "" : " (" + e.detail + ")");
}

}  // namespace yardsim::models
