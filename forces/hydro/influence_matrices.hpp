#pragma once
// The influence matrices of a panel set on its own collocation points (the panel centroids x_i):
//   S_ij = S_j(x_i) - S_j(x_i'),  D_ij = D_j(x_i) - D_j(x_i')
// with S_j, D_j the source and dipole integrals over panel j (rankine_integrals.hpp) and x_i' the
// mirror image of x_i in the mean water plane z = 0 when the free surface is the infinite-
// frequency one (phi = 0 on z = 0: the Green function 1/r - 1/r', a negative image); without a
// free surface (a body deep in unbounded fluid) the image terms are absent.
#include <vector>

#include <Eigen/Core>

#include "forces/hydro/panel_geometry.hpp"

namespace yardsim::forces::hydro {

enum class FreeSurface {
  None,          ///< unbounded fluid
  NegativeImage  ///< phi = 0 on z = 0 (infinite frequency), fluid in z < 0
};

struct InfluenceMatrices {
  Eigen::MatrixXd source;  ///< S, N x N
  Eigen::MatrixXd dipole;  ///< D, N x N (D_ii = 0: flat panels)
};

/// (panels, free surface) => S and D; allocates 2 N^2 doubles.
InfluenceMatrices assembleInfluence(const std::vector<Panel>& panels, FreeSurface fs);

/// x mirrored in z = 0.
inline Vector3 mirrorInWaterPlane(const Vector3& x) { return {x.x(), x.y(), -x.z()}; }

}  // namespace yardsim::forces::hydro
