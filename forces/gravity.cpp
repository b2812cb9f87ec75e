#include "forces/gravity.hpp"

#include <stdexcept>

#include "dynamics/kinematics.hpp"

namespace yardsim::forces {

Gravity::Gravity(std::string name, const dynamics::Vector3& g_W)
    : ForceProvider(std::move(name)), g_W_(g_W) {
  if (!g_W_.allFinite())
    throw std::invalid_argument("gravity '" + this->name() + "': g must be finite");
}

void Gravity::doEvaluate(const Stage& s, dynamics::ExternalForces& f,
                         Eigen::VectorXd& /*tau*/) const {
  // (X_WB, m_i, c_i) => f_W = m_i g_W at p_W = X_WB c_i
  for (int b = 1; b < s.model.nbodies; ++b) {
    const dynamics::SpatialInertia& I = s.model.inertias[b];
    if (I.mass == 0.0) continue;
    f.addPointForceWorld(b, dynamics::pointPosition(s.data, b, I.com), I.mass * g_W_);
  }
}

double Gravity::doPotentialEnergy(const Stage& s) const {
  // (X_WB, m_i, c_i) => -sum m_i g_W . p_com_W
  double V = 0.0;
  for (int b = 1; b < s.model.nbodies; ++b) {
    const dynamics::SpatialInertia& I = s.model.inertias[b];
    V -= I.mass * g_W_.dot(dynamics::pointPosition(s.data, b, I.com));
  }
  return V;
}

}  // namespace yardsim::forces
