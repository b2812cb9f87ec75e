#include "mechanics/shared_stage.hpp"

#include <algorithm>

#include "mechanics/follow_mass.hpp"

namespace yardsim::mechanics {

bool stageShareable(const System& s, const Data& d) {
  if (followsMass(s)) return false;
  const auto& providers = s.providers();
  // (provider i) => it is one of the system's ropes (wire ropes and equalizers)
  auto isRope = [&s](const forces::ForceProvider* p) {
    return std::any_of(s.ropes().begin(), s.ropes().end(),
                       [p](const auto& r) { return r.get() == p; });
  };
  for (std::size_t i = 0; i < providers.size(); ++i) {
    if (providers[i]->switches()) return false;
    if (d.providerScratch[i] != nullptr && !isRope(providers[i])) return false;
  }
  return true;
}

}  // namespace yardsim::mechanics
