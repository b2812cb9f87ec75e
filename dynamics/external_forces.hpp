#pragma once
// External spatial forces applied to bodies, given per body in the body frame (about the body
// origin) or in the world frame (about the world origin). Preallocated from the model.

#include <vector>

#include "dynamics/data.hpp"
#include "dynamics/model.hpp"

namespace yardsim::dynamics {

class ExternalForces {
 public:
  explicit ExternalForces(const Model& model);

  /// Sets every force to zero.
  void clear();
  /// Adds F_B_B: a spatial force on body B expressed in B about B's origin.
  void addBodyFrame(int body, const Force& F_B_B);
  /// Adds F_B_W: a spatial force on body B expressed in the world about the world origin.
  void addWorldFrame(int body, const Force& F_B_W);
  /// Adds a force f_W (world frame) acting at the world point p_W on body B.
  void addPointForceWorld(int body, const Vector3& p_W, const Vector3& f_W);

  bool hasWorldFrame() const { return hasWorld_; }
  bool empty() const { return !hasWorld_ && !hasBody_; }
  const Force& bodyFrame(int body) const { return body_[body]; }
  const Force& worldFrame(int body) const { return world_[body]; }

  /// (X_WB of every body) => F_B_B total for body i in its own frame.
  Force inBodyFrame(const Data& data, int body) const {
    return hasWorld_ ? Force(body_[body] + data.X_WB[body].invActForce(world_[body])) : body_[body];
  }

 private:
  std::vector<Force> body_;
  std::vector<Force> world_;
  bool hasWorld_ = false;
  bool hasBody_ = false;
};

}  // namespace yardsim::dynamics
