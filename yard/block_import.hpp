#pragma once
// A block's figures from its geometry: a STEP file (B-rep properties, tessellated mesh) or an
// OBJ/STL mesh (the mesh's own properties), with a density, or with a stated mass and cog.
#include <optional>
#include <string>

#include "forces/geometry/step_reader.hpp"
#include "yard/records.hpp"

namespace yardsim::yard {

struct BlockSource {
  std::string geometry;                      // .step/.stp/.obj/.stl file; empty: none
  std::optional<double> density;             // kg/m^3: mass = density x volume, cog = centroid
  std::optional<double> mass;                // kg, with cog (instead of density)
  std::optional<dynamics::Vector3> cog;      // m, block frame
  std::optional<dynamics::Matrix3> inertia;  // kg m^2 about the cog; else from the geometry
  forces::StepTolerance tolerance;           // for STEP files
};

// (name, source) => the block: with a density, mass, cog and inertia of the homogeneous solid;
// with mass and cog, the inertia given or that of the solid scaled to the mass and moved to the
// cog (parallel axes). DatabaseError for a missing file, a mesh that is not closed, a density or
// mass <= 0, neither or both of density and mass, a mass without cog or without geometry and
// inertia. The block's source records the file and the method.
Block blockFromSource(const std::string& name, const BlockSource& source);

}  // namespace yardsim::yard
