#include "mechanics/follow_mass.hpp"

#include "mechanics/follow_draft.hpp"

namespace yardsim::mechanics {

void followMass(const System& s, double t, const dynamics::Data& kin, dynamics::Data& target) {
  followDraft(s, kin, target);
  // (winched lines, t) => per inner node (a translation joint, body frame = world frame) the mass
  // beyond the model's on the linear block, [angular; linear]
  for (const forces::LumpedLineProvider* line : s.winchedLines())
    for (int i = 1; i < line->line().properties().segments; ++i) {
      const auto b = static_cast<std::size_t>(line->nodeBody(i));
      const double dm = line->nodeMass(i, t) - s.model().inertias[b].mass;
      target.addedMass[b].setZero();
      target.addedMass[b].bottomRightCorner<3, 3>().diagonal().setConstant(dm);
      target.hasAddedMass[b] = dm != 0.0;
    }
}

}  // namespace yardsim::mechanics
