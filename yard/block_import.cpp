#include "yard/block_import.hpp"

#include <cmath>
#include <filesystem>

#include "forces/geometry/mesh_io.hpp"
#include "yard/database.hpp"
#include "yard/physical_checks.hpp"

namespace yardsim::yard {

using dynamics::Matrix3;
using dynamics::Vector3;

Block blockFromSource(const std::string& name, const BlockSource& s) {
  Block b;
  b.name = name;
  const std::string what = "block '" + name + "'";
  if (s.density.has_value() == s.mass.has_value())
    throw DatabaseError(what + ": give either --density or --mass with --cog");
  // (geometry file) => the mesh and the unit-density solid (the B-rep's for STEP)
  std::optional<forces::SolidProperties> solid;
  if (!s.geometry.empty()) {
    if (!std::filesystem::is_regular_file(s.geometry))
      throw DatabaseError(s.geometry + ": no such file");
    try {
      const std::string ext = std::filesystem::path(s.geometry).extension().string();
      if (ext == ".step" || ext == ".stp" || ext == ".STEP" || ext == ".STP") {
        forces::StepModel m = forces::readStep(s.geometry, s.tolerance);
        solid = m.brep;
        b.mesh = std::make_shared<const forces::TriangleMesh>(std::move(m.mesh));
        b.source = s.geometry + " (STEP B-rep, " + std::to_string(m.solids) + " solid(s))";
      } else {
        forces::TriangleMesh mesh = forces::readClosedMesh(s.geometry);
        solid = forces::solidProperties(mesh);
        b.mesh = std::make_shared<const forces::TriangleMesh>(std::move(mesh));
        b.source = s.geometry + " (closed mesh)";
      }
    } catch (const forces::MeshError& e) {
      throw DatabaseError(std::string(e.what()));
    }
  }
  if (s.density) {
    if (!(*s.density > 0) || !std::isfinite(*s.density))
      throw DatabaseError(what + ": the density must be > 0 kg/m^3");
    if (!solid)
      throw DatabaseError(what + ": --density needs a geometry file (--step, --obj or --stl)");
    b.mass = *s.density * solid->volume;
    b.cog = solid->centroid;
    b.inertia = *s.density * solid->inertia;
    b.weightStatus = "calculated";
    b.source += ", density " + std::to_string(*s.density) + " kg/m^3";
  } else {
    checkMass(*s.mass, what);
    if (!s.cog) throw DatabaseError(what + ": --mass needs --cog x,y,z (m, block frame)");
    b.mass = *s.mass;
    b.cog = *s.cog;
    if (s.inertia) {
      b.inertia = *s.inertia;
    } else if (solid) {
      // (solid scaled to the mass, about its centroid) => about the stated cog
      const Vector3 d = solid->centroid - b.cog;
      b.inertia = b.mass / solid->volume * solid->inertia +
                  b.mass * (d.squaredNorm() * Matrix3::Identity() - d * d.transpose());
    } else {
      throw DatabaseError(
          what + ": --mass without a geometry file needs --inertia (kg m^2 about the cog)");
    }
    b.source += b.source.empty() ? "stated mass and cog" : ", stated mass and cog";
  }
  checkInertia(b.inertia, what);
  return b;
}

}  // namespace yardsim::yard
