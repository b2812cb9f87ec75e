#pragma once
// Uniform gravity as a force provider: m_i g_W at the centre of mass of every body, potential
// energy -sum m_i g_W . p_com_i (zero at the world origin). A scene builds its dynamics::Model
// with zero model gravity and uses this provider instead, so that gravity's work appears in the
// energy balance with every other provider's.
#include <string>

#include "forces/force_provider.hpp"

namespace yardsim::forces {

class Gravity final : public ForceProvider {
 public:
  // (name, g_W: acceleration of gravity in the world frame, m/s^2) => the provider; throws
  // std::invalid_argument when g_W is not finite
  Gravity(std::string name, const dynamics::Vector3& g_W);

  const dynamics::Vector3& gravity() const { return g_W_; }

 protected:
  void doEvaluate(const Stage& s, dynamics::ExternalForces& f, Eigen::VectorXd& tau) const override;
  double doPotentialEnergy(const Stage& s) const override;

 private:
  dynamics::Vector3 g_W_;
};

}  // namespace yardsim::forces
