#include "mechanics/data.hpp"

#include <cstring>

#include "dynamics/kinematics.hpp"

namespace yardsim::mechanics {

Data::Data(const System& s)
    : kernel(s.model()),
      scratch(s.model()),
      scratch2(s.model()),
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
  for (auto& slot : slots) {
    slot.q = Eigen::VectorXd::Zero(s.model().nq);
    slot.v = Eigen::VectorXd::Zero(s.model().nv);
  }
  for (const forces::ForceProvider* p : s.providers()) providerScratch.push_back(p->makeScratch());
}

dynamics::Data& Data::scratchKinematics(const System& s, const Eigen::VectorXd& q,
                                        const Eigen::VectorXd& v) {
  // (q, v bit for bit those a slot was computed at, nothing written since) => that slot as it is
  const auto same = [](const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
    const auto bytes = sizeof(double) * static_cast<std::size_t>(a.size());
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), bytes) == 0;
  };
  for (int k = 0; k < 2; ++k)
    if (slots[k].holds && same(q, slots[k].q) && same(v, slots[k].v)) {
      lastSlot = k;
      return k == 0 ? scratch : scratch2;
    }
  // (neither) => the slot used less recently
  lastSlot = 1 - lastSlot;
  KinematicsSlot& slot = slots[lastSlot];
  dynamics::Data& kin = lastSlot == 0 ? scratch : scratch2;
  dynamics::forwardKinematics(s.model(), kin, q, v);
  slot.q = q;
  slot.v = v;
  slot.holds = true;
  return kin;
}

forces::ProviderScratch* Data::scratchOf(const System& s, const forces::ForceProvider& p) const {
  const auto& providers = s.providers();
  for (std::size_t i = 0; i < providers.size(); ++i)
    if (providers[i] == &p) return providerScratch[i].get();
  return nullptr;
}

}  // namespace yardsim::mechanics
