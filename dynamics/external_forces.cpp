#include "dynamics/external_forces.hpp"

namespace yardsim::dynamics {

ExternalForces::ExternalForces(const Model& m) : body_(m.nbodies, Force::Zero()), world_(m.nbodies, Force::Zero()) {}

void ExternalForces::clear() {
  if (empty()) return;  // nothing was added since the last clear
  for (auto& f : body_) f.setZero();
  for (auto& f : world_) f.setZero();
  hasWorld_ = hasBody_ = false;
}

void ExternalForces::addBodyFrame(int body, const Force& F_B_B) {
  body_[body] += F_B_B;
  hasBody_ = true;
}

void ExternalForces::addWorldFrame(int body, const Force& F_B_W) {
  world_[body] += F_B_W;
  hasWorld_ = true;
}

void ExternalForces::addPointForceWorld(int body, const Vector3& p_W, const Vector3& f_W) {
  Force F;
  F.head<3>() = p_W.cross(f_W);
  F.tail<3>() = f_W;
  addWorldFrame(body, F);
}

}  // namespace yardsim::dynamics
