#pragma once
// Current load on one body: the OCIMF-style drag of forces/flow_load.hpp with the flow taken from
// the current field (forces/current_profile.hpp) at the body's reference point (its depth picks
// the speed from the profile), in water: the areas are the underwater projected areas (fixed:
// they do not follow the draft).
#include <memory>

#include "forces/current_profile.hpp"
#include "forces/flow_load.hpp"

namespace yardsim::forces {

class CurrentLoad final : public FlowLoad {
 public:
  // (name, model, body, reference point p_B, areas, coefficients, the current, water density) =>
  // the provider; throws std::invalid_argument naming it
  CurrentLoad(std::string name, const dynamics::Model& model, int body, const dynamics::Vector3& p_B,
              const FlowAreas& areas, FlowCoefficients coefficients, std::shared_ptr<const CurrentField> field,
              double waterDensity = 1025.0);

  const CurrentField& field() const { return *field_; }

 protected:
  dynamics::Vector3 flowVelocity(const dynamics::Vector3& p_W, double t) const override;

 private:
  std::shared_ptr<const CurrentField> field_;
};

}  // namespace yardsim::forces
