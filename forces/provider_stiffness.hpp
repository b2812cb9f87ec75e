#pragma once
// The stiffness a provider may bring in later in a run (a contact that is open at the start):
// the linearisation of the stiffness estimate (mechanics/stiffness_estimate.hpp) sees only what
// acts at the initial state, so a provider that implements ProviderStiffness states the highest
// frequency it can excite once engaged, and the estimate takes the larger of the two.
#include <string>

#include "dynamics/model.hpp"

namespace yardsim::forces {

struct StiffnessHint {
  double omega = 0.0;  // rad/s, the highest frequency (or decay rate) once engaged
  std::string body;    // the body that moves in that mode
  std::string what;    // "contact normal", "contact friction"
};

class ProviderStiffness {
 public:
  virtual ~ProviderStiffness() = default;
  // (model) => the hint
  virtual StiffnessHint stiffnessHint(const dynamics::Model& model) const = 0;
};

}  // namespace yardsim::forces
