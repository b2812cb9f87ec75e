#include "forces/current_load.hpp"

#include <stdexcept>

namespace yardsim::forces {

CurrentLoad::CurrentLoad(std::string name, const dynamics::Model& model, int body, const dynamics::Vector3& p_B,
                         const FlowAreas& areas, FlowCoefficients coefficients,
                         std::shared_ptr<const CurrentField> field, double waterDensity)
    : FlowLoad(name, model, body, p_B, areas, std::move(coefficients), waterDensity), field_(std::move(field)) {
  if (!field_) throw std::invalid_argument("current load '" + this->name() + "': no current field given");
}

dynamics::Vector3 CurrentLoad::flowVelocity(const dynamics::Vector3& p_W, double /*t*/) const {
  return field_->velocity(p_W);
}

}  // namespace yardsim::forces
