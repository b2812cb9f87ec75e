#include "forces/wind_load.hpp"

#include <stdexcept>

namespace yardsim::forces {

namespace {
const WindField& checked(const std::shared_ptr<const WindField>& f, const std::string& name) {
  if (!f) throw std::invalid_argument("wind load '" + name + "': no wind field given");
  return *f;
}
}  // namespace

WindLoad::WindLoad(std::string name, const dynamics::Model& model, int body, const dynamics::Vector3& p_B,
                   const FlowAreas& areas, FlowCoefficients coefficients, std::shared_ptr<const WindField> field)
    : FlowLoad(name, model, body, p_B, areas, std::move(coefficients),
               checked(field, name).properties().density),
      field_(std::move(field)) {}

dynamics::Vector3 WindLoad::flowVelocity(const dynamics::Vector3& p_W, double t) const {
  return field_->velocity(p_W, t);
}

}  // namespace yardsim::forces
