#pragma once
// Wind load on one body: the OCIMF-style drag of forces/flow_load.hpp with the flow taken from
// the wind field (forces/wind_profile.hpp) at the body's reference point (its height picks the
// speed from the profile), in air.
#include <memory>

#include "forces/flow_load.hpp"
#include "forces/wind_profile.hpp"

namespace yardsim::forces {

class WindLoad final : public FlowLoad {
 public:
  // (name, model, body, reference point p_B, areas, coefficients, the wind) =>
  // the provider; throws std::invalid_argument naming it
  WindLoad(std::string name, const dynamics::Model& model, int body, const dynamics::Vector3& p_B,
           const FlowAreas& areas, FlowCoefficients coefficients, std::shared_ptr<const WindField> field);

  const WindField& field() const { return *field_; }

 protected:
  dynamics::Vector3 flowVelocity(const dynamics::Vector3& p_W, double t) const override;

 private:
  std::shared_ptr<const WindField> field_;
};

}  // namespace yardsim::forces
