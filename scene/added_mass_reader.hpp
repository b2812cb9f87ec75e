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
#include "mechanics/description.hpp"
#include "scene/spec_reader.hpp"

namespace yardsim::scene {

using mechanics::MechanicsSpec;

/// (reader, the `added_mass` node, its key path, the YAML file naming it) => b.addedMass or
/// b.addedMassHull (read, checked as a closed surface and as panels), with b.addedMassDrafts
/// when it follows the draft (`follow_draft: [m, ...]`); problems reported at
/// their node.
void parseAddedMass(const spec::Reader& r, const YAML::Node& n, const std::string& key, const std::string& yamlFile,
                    MechanicsSpec::Body& b);

}  // namespace yardsim::scene
