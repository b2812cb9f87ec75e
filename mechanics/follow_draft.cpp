#include "mechanics/follow_draft.hpp"

namespace yardsim::mechanics {

void followDraft(const System& s, const dynamics::Data& kin, dynamics::Data& target) {
  // (X_WB of each draft-following body) => its interpolated A and whether it is wet
  dynamics::Matrix6 slope;
  for (const auto& p : s.draftAddedMass()) {
    const auto i = static_cast<std::size_t>(p->body());
    target.hasAddedMass[i] = p->interpolate(p->draft(kin.X_WB[i]), target.addedMass[i], slope);
  }
}

}  // namespace yardsim::mechanics
