#include "forces/force_provider.hpp"

namespace yardsim::forces {

namespace {
static_assert(sizeof(dynamics::Force) == 6 * sizeof(double), "spatial forces stored back to back");
// (bodies 1 .. n-1 of a frame's spatial forces, stored back to back) => true when every
// coefficient is finite: x * 0 is 0 for a finite x and NaN for an infinite or NaN one, so one
// vectorised sum decides, without a branch per body (the stage checks after every provider)
bool allFinite(const dynamics::Force& first, int bodies) {
  if (bodies <= 0) return true;
  return (Eigen::Map<const Eigen::VectorXd>(first.data(), 6 * bodies).array() * 0.0).sum() == 0.0;
}
}  // namespace

bool forcesFinite(const dynamics::Model& model, const dynamics::ExternalForces& f,
                  const Eigen::VectorXd& tau) {
  const int n = model.nbodies - 1;
  return (n <= 0 || (allFinite(f.bodyFrame(1), n) &&
                     (!f.hasWorldFrame() || allFinite(f.worldFrame(1), n)))) &&
         tau.allFinite();
}

void ForceProvider::evaluate(const Stage& s, dynamics::ExternalForces& f,
                             Eigen::VectorXd& tau) const {
  doEvaluate(s, f, tau);
  // (accumulated forces) => finite, or a diagnosis naming this provider; a non-finite total
  // appears first after the provider that made it
  if (forcesFinite(s.model, f, tau)) return;
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
