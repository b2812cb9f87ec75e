#include "mechanics/data.hpp"

namespace yardsim::mechanics {

Data::Data(const System& s)
    : kernel(s.model()),
      scratch(s.model()),
      view(s.model()),
      feedforward(s.model()),
      drivenJoints(static_cast<std::size_t>(s.model().nbodies), 0),
      reaction(s.model()),
      spForces(s.model()),
      spTau(Eigen::VectorXd::Zero(s.model().nv)),
      prescribedMask(static_cast<std::size_t>(s.model().nv), 0),
      prescribedAcc(Eigen::VectorXd::Zero(s.model().nv)),
      accelScratch(Eigen::VectorXd::Zero(s.model().nv)) {
  feedforwardMask.mark(s.model(), drivenJoints);  // (sized once: a stage marks it again)
  for (const forces::ForceProvider* p : s.providers()) providerScratch.push_back(p->makeScratch());
}

forces::ProviderScratch* Data::scratchOf(const System& s, const forces::ForceProvider& p) const {
  const auto& providers = s.providers();
  for (std::size_t i = 0; i < providers.size(); ++i)
    if (providers[i] == &p) return providerScratch[i].get();
  return nullptr;
}

}  // namespace yardsim::mechanics
