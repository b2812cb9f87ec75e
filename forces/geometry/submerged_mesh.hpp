#pragma once
// The part of a closed hull below the water surface, at a given pose and time: each triangle is
// clipped at the surface (the depth eta(x, y, t) - z is linear along an edge between corners),
// and the wetted pieces give, by signed tetrahedra from a point on the surface (Ku et al. 2014),
// the submerged volume and centre of buoyancy, and by the divergence theorem the waterplane
// area, centroid and second moments; the incident pressure integrated over the wetted pieces
// (three-point edge-midpoint rule, exact for the linear pressure of calm water) gives the force
// and moment. In calm water everything is exact for the polyhedron. Allocation-free.
#include <array>
#include <vector>

#include <Eigen/Core>

#include "forces/airy_waves.hpp"
#include "forces/geometry/triangle_mesh.hpp"

namespace yardsim::forces {

struct SubmergedProperties {
  double volume = 0.0;  // m^3 below the surface (waves: see docs/hydrostatics.md)
  dynamics::Vector3 centreOfBuoyancy = dynamics::Vector3::Zero();  // world, m
  double waterplaneArea = 0.0;                                     // m^2, projected on the horizontal
  Eigen::Vector2d waterplaneCentroid = Eigen::Vector2d::Zero();    // world x, y, m
  // world-axis second moments of the waterplane about its centroid, m^4:
  // [[int (x-xc)^2, int (x-xc)(y-yc)], [., int (y-yc)^2]]
  Eigen::Matrix2d waterplaneInertia = Eigen::Matrix2d::Zero();
  double wettedArea = 0.0;                              // m^2
  dynamics::Vector3 force = dynamics::Vector3::Zero();   // N, world: -int p n dS
  dynamics::Vector3 moment = dynamics::Vector3::Zero();  // N m, world, about the world origin
  int wetTriangles = 0;  // pieces stored in the workspace (when asked for)
};

// Buffers sized for one mesh: its vertices in the world, their depths, the wetted pieces, and the
// mesh's edges with the pressure at their midpoints (built once, here).
struct SubmergedWorkspace {
  // (mesh, the sea's wave components) => buffers and the edge numbering of its triangles
  explicit SubmergedWorkspace(const TriangleMesh& mesh, std::size_t components = 0);
  std::vector<dynamics::Vector3> vertices;  // world, m
  // eta(x, y, t) - z, m (> 0: wet); in waves -inf for a corner above the highest crest at t
  // (dry) whose depth no crossing edge asked for
  std::vector<double> depth;
  std::vector<std::array<dynamics::Vector3, 3>> wet;  // wetted pieces, world, outward (first wetTriangles)
  // edge[3 t + e]: the number of triangle t's edge from its corner e to corner e + 1, the same for
  // every triangle with those two corners; edgePressure[k] is the incident pressure (Pa) at the
  // midpoint of edge k's wet part (the whole edge, or in waves the part from its wet end to where
  // it crosses the surface), valid in the call whose number is edgeStamp[k] (one evaluation per
  // wet edge, not one per triangle that shares it)
  std::vector<int> edge;
  std::vector<double> edgePressure;
  std::vector<unsigned> edgeStamp;
  unsigned call = 0;
  // halfPhase[2 m i ...]: the sea's m components' half phases at corner i (AiryWaves::halfPhases),
  // sized for `components` (or at the first call in a sea of more): a mesh edge's midpoint
  // pressure comes from its two corners'
  std::vector<double> halfPhase;
};

// Which integrals integrateSubmerged computes: all of them, or the pressure force and moment
// alone (the same doubles as with All, by the same operations; the other fields stay zero)
enum class SubmergedIntegrals { All, Force };

// (mesh in the body frame, X_WB, sea, t, workspace built for this mesh, keep the wetted pieces,
// which integrals) => submerged properties and the pressure force of the sea on the wetted surface
SubmergedProperties integrateSubmerged(const TriangleMesh& mesh, const dynamics::Transform& X_WB,
                                       const AiryWaves& sea, double t, SubmergedWorkspace& ws,
                                       bool keepWet = false,
                                       SubmergedIntegrals which = SubmergedIntegrals::All);

}  // namespace yardsim::forces
