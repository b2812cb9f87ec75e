#include "mechanics/added_mass_build.hpp"

#include <algorithm>

#include "dynamics/added_mass.hpp"
#include "dynamics/data.hpp"
#include "dynamics/kinematics.hpp"
#include "forces/hydro/added_mass.hpp"

namespace yardsim::mechanics {

void setGivenAddedMass(const std::vector<MechanicsSpec::Body>& bodies,
                       dynamics::ModelBuilder& builder) {
  for (const auto& b : bodies) {
    if (b.addedMass)
      builder.setAddedMass(b.name, dynamics::addedMassAboutOrigin(*b.addedMass, b.addedMassAbout));
  }
}

bool needsHullAddedMass(const std::vector<MechanicsSpec::Body>& bodies) {
  return std::any_of(bodies.begin(), bodies.end(),
                     [](const auto& b) { return b.addedMassHull != nullptr; });
}

void setHullAddedMass(const dynamics::Model& model, const Eigen::VectorXd& q0,
                      const MechanicsSpec& spec, dynamics::ModelBuilder& builder) {
  // (q0) => X_WB of each body at its mean position
  dynamics::Data d(model);
  dynamics::forwardKinematics(model, d, q0);
  for (const auto& b : spec.bodies) {
    if (!b.addedMassHull) continue;
    const int i = model.bodyIndex(b.name);
    const double rho = b.addedMassRho > 0.0 ? b.addedMassRho : spec.water.density;
    try {
      // (hull, X_WB, water) => body-axes added mass about the origin, symmetrised (the discrete
      // one is symmetric to discretisation accuracy only)
      const dynamics::Matrix6 A = forces::hydro::floatingAddedMass(
          forces::hydro::panelMesh(*b.addedMassHull), d.X_WB[static_cast<std::size_t>(i)], rho,
          spec.water.level);
      builder.setAddedMass(b.name, dynamics::addedMassAboutOrigin(0.5 * (A + A.transpose()),
                                                                  dynamics::Vector3::Zero()));
    } catch (const std::exception& e) {
      throw dynamics::ModelError("body '" + b.name + "': added mass from hull '" +
                                 b.addedMassHull->source + "': " + e.what());
    }
  }
}

}  // namespace yardsim::mechanics
