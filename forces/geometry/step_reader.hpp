#pragma once
// STEP (ISO 10303 AP203/AP214/AP242) solids as triangle meshes, through OpenCASCADE (OCCT).
// Every solid of the file, assemblies flattened with their placements, is tessellated into one
// closed, outward-oriented TriangleMesh that checkClosedMesh accepts (one connected part per
// solid; a cavity must open to the outside, a sealed void would be a part of negative volume).
// Lengths are converted to metres whatever unit the file states. Volume, centroid and inertia
// come from the exact B-rep (OCCT's global properties) and are returned beside the mesh; the
// mesh's own solidProperties agree with them to the tessellation tolerance. No OCCT type
// appears here. A build without OCCT (YARDSIM_WITH_STEP=OFF) throws MeshError from readStep.
#include <string>

#include "forces/geometry/triangle_mesh.hpp"

namespace yardsim::forces {

// Tessellation tolerance: the largest distance between a triangle and the true surface (chord
// height, m, absolute) and the largest angle between neighbouring facets along a curved
// surface (rad). Planar faces are split only as their outlines need.
struct StepTolerance {
  double chord = 1e-3;  // m
  double angle = 0.35;  // rad (about 20 degrees)
};

// A STEP file's solids: the mesh (m, the file's global frame) and the exact properties.
struct StepModel {
  TriangleMesh mesh;        // closed, outward; source = path
  SolidProperties brep;     // from the B-rep at density 1 kg/m^3 (inertia about the centroid)
  int solids = 0;           // solids found (assembly leaves flattened)
  StepTolerance tolerance;  // the tolerance the mesh was made with
};

// (path, tolerance) => the solids of the STEP file, meshed, checked with checkClosedMesh, and
// their B-rep properties. Throws MeshError naming the file: unreadable or not STEP, no solid in
// it, a solid whose tessellation is not closed, or a build without STEP support.
StepModel readStep(const std::string& path, const StepTolerance& tolerance = {});

// () => whether this build reads STEP files (compiled with OCCT)
bool stepSupported();

}  // namespace yardsim::forces
