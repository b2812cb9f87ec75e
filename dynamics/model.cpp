#include "dynamics/model.hpp"

namespace yardsim::dynamics {

int Model::bodyIndex(std::string_view name) const {
  for (int i = 0; i < nbodies; ++i) {
    if (names[i] == name) return i;
  }
  return -1;
}

double Model::totalMass() const {
  double m = 0.0;
  for (int i = 1; i < nbodies; ++i) m += inertias[i].mass;
  return m;
}

}  // namespace yardsim::dynamics
