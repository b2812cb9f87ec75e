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
                     [](const auto& b) { return b.addedMassHull && b.addedMassDrafts.empty(); });
}

void setHullAddedMass(const dynamics::Model& model, const Eigen::VectorXd& q0,
                      const MechanicsSpec& spec, dynamics::ModelBuilder& builder) {
  // (q0) => X_WB of each body at its mean position
  dynamics::Data d(model);
  dynamics::forwardKinematics(model, d, q0);
  for (const auto& b : spec.bodies) {
    if (!b.addedMassHull || !b.addedMassDrafts.empty()) continue;
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

std::vector<BuiltMechanics::DraftAddedMass> draftAddedMassTables(const dynamics::Model& model,
                                                                 const Eigen::VectorXd& q0,
                                                                 const MechanicsSpec& spec) {
  std::vector<BuiltMechanics::DraftAddedMass> out;
  dynamics::Data d(model);
  bool placed = false;
  for (const auto& b : spec.bodies) {
    if (!b.addedMassHull || b.addedMassDrafts.empty()) continue;
    // (q0) => the body's attitude at set-up
    if (!placed) dynamics::forwardKinematics(model, d, q0);
    placed = true;
    const int i = model.bodyIndex(b.name);
    const double rho = b.addedMassRho > 0.0 ? b.addedMassRho : spec.water.density;
    try {
      // (hull, attitude, drafts) => A-infinity at each draft by the panel solver
      out.push_back({b.name, std::make_shared<const forces::hydro::DraftAddedMassTable>(
                                 forces::hydro::draftAddedMassTable(
                                     forces::hydro::panelMesh(*b.addedMassHull),
                                     d.X_WB[static_cast<std::size_t>(i)].R, b.addedMassDrafts, rho,
                                     spec.water.level))});
    } catch (const std::exception& e) {
      throw dynamics::ModelError("body '" + b.name + "': added mass from hull '" +
                                 b.addedMassHull->source + "' at drafts: " + e.what());
    }
  }
  return out;
}

}  // namespace yardsim::mechanics
