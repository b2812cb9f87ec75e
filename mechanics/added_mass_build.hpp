#pragma once
// Added mass into the model builder (docs/hydrodynamics.md): given 6x6 matrices (naval order,
// kg, kg m, kg m^2, about a point of the body frame) or computed by the Rankine-panel solver from
// a hull mesh at the body's initial (mean) pose, or tabulated against the draft.
#include <vector>

#include <Eigen/Core>

#include "dynamics/model.hpp"
#include "dynamics/model_builder.hpp"
#include "mechanics/description.hpp"

namespace yardsim::mechanics {

/// (bodies) => builder.setAddedMass for each body with a given matrix.
void setGivenAddedMass(const std::vector<MechanicsSpec::Body>& bodies,
                       dynamics::ModelBuilder& builder);

/// True when a body asks for a constant added mass from a hull mesh.
bool needsHullAddedMass(const std::vector<MechanicsSpec::Body>& bodies);

/// (model without those, initial q, spec: bodies and water) => builder.setAddedMass for each body
/// with a hull, computed at the pose of q0; throws dynamics::ModelError naming the body (a dry
/// hull).
void setHullAddedMass(const dynamics::Model& model, const Eigen::VectorXd& q0,
                      const MechanicsSpec& spec, dynamics::ModelBuilder& builder);

/// (final model, initial q, spec: bodies and water) => for each body whose added mass follows its
/// draft, its table by the panel solver at its attitude at q0; throws dynamics::ModelError naming
/// the body.
std::vector<BuiltMechanics::DraftAddedMass> draftAddedMassTables(const dynamics::Model& model,
                                                                 const Eigen::VectorXd& q0,
                                                                 const MechanicsSpec& spec);

}  // namespace yardsim::mechanics
