#include "forces/force_provider.hpp"

namespace yardsim::forces {

void ForceProvider::evaluate(const Stage& s, dynamics::ExternalForces& f,
                             Eigen::VectorXd& tau) const {
  doEvaluate(s, f, tau);
  // (accumulated forces) => finite, or a diagnosis naming this provider; a non-finite total
  // appears first after the provider that made it
  for (int b = 1; b < s.model.nbodies; ++b) {
    if (f.bodyFrame(b).allFinite() && (!f.hasWorldFrame() || f.worldFrame(b).allFinite())) continue;
    throw ForceError("force provider '" + name_ + "' produced a non-finite force on body '" +
                     s.model.names[b] + "' at t = " + std::to_string(s.t) +
                     " s; check its parameters, or take a smaller step");
  }
  if (!tau.allFinite())
    throw ForceError("force provider '" + name_ +
                     "' produced a non-finite joint force at t = " + std::to_string(s.t) + " s");
}

}  // namespace yardsim::forces
