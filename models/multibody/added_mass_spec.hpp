#pragma once
// The `added_mass` key of a body in a mechanics fragment (docs/hydrodynamics.md), either given
//   added_mass: {matrix: [[6 numbers], ... 6 rows], about: [x, y, z]}
// (naval order surge, sway, heave, roll, pitch, yaw; kg, kg m, kg m^2; about the point `about`
// of the body frame, default its origin; body axes), or computed by the Rankine-panel solver
//   added_mass: {hull: pontoon.obj, rho: 1025}
// from a closed hull mesh in the body frame (path relative to the YAML file) at the body's
// initial (mean) position: the part below the still-water level (the scene's `water: {level}`,
// default z = 0), infinite frequency; rho defaults to the scene's water density (1025 kg/m^3).
#include <string>

#include <Eigen/Core>
#include <yaml-cpp/yaml.h>

#include "dynamics/model.hpp"
#include "dynamics/model_builder.hpp"
#include "models/multibody/mechanics_spec.hpp"
#include "models/multibody/spec_reader.hpp"

namespace yardsim::models {

/// (reader, the `added_mass` node, its key path, the YAML file naming it) => b.addedMass or
/// b.addedMassHull (read, checked as a closed surface and as panels); problems reported at
/// their node.
void parseAddedMass(const spec::Reader& r, const YAML::Node& n, const std::string& key, const std::string& yamlFile,
                    MechanicsSpec::Body& b);

/// (bodies) => builder.setAddedMass for each body with a given matrix.
void setGivenAddedMass(const std::vector<MechanicsSpec::Body>& bodies, dynamics::ModelBuilder& builder);

/// True when a body asks for its added mass from a hull mesh.
bool needsHullAddedMass(const std::vector<MechanicsSpec::Body>& bodies);

/// (model without those, initial q, spec: bodies and water) => builder.setAddedMass for each body
/// with a hull, computed at the pose of q0; throws dynamics::ModelError naming the body (a dry hull).
void setHullAddedMass(const dynamics::Model& model, const Eigen::VectorXd& q0, const MechanicsSpec& spec,
                      dynamics::ModelBuilder& builder);

}  // namespace yardsim::models
