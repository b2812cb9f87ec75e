#pragma once
// The mixed boundary-value problem of the time-domain Rankine-panel method, on the mean wetted
// hull (panels b, the potential phi unknown, its normal derivative phi_n given) and the mean free
// surface z = 0 out to the truncation radius (panels f, phi given, phi_n unknown). World frame at
// the mean position, z up, normals out of the body and of the free surface into the fluid (-z on
// the free surface, so there phi_n = -phi_z). Units: phi m^2/s (or its time derivative m^2/s^2),
// phi_n m/s (or m/s^2); both columns may carry any linear quantity that is harmonic in the fluid.
//
// Green's second identity at each collocation point x_i (constant panels, centroids), with S_ij,
// D_ij the Rankine source and dipole integrals of panel j at x_i (plus those at the sea-bed image
// x_i'' = (x, y, -2 h - z) for a finite depth h, the Green function 1/r + 1/r''):
//   2 pi phi_i - sum_j D_ij phi_j = - sum_j S_ij phi_n,j
// Sorted by what is unknown, for all rows i:
//   sum_{j in b} (2 pi d_ij - D_ij) phi_j + sum_{j in f} S_ij phi_n,j
//       = - sum_{j in b} S_ij phi_n,j + sum_{j in f} (D_ij - 2 pi d_ij) phi_j
// i.e. M u = R_b a + R_f p with u = [phi_b; phi_n,f], a = phi_n,b, p = phi_f. M is assembled and
// factorised once for the fixed geometry (LAPACK's DGETRF, partial pivoting: OpenBLAS), and the
// solution map A = M^-1 [R_b R_f] (N x N) formed from the factors by two triangular solves with N
// columns (DTRSM); M's factors and R are then dropped. Every time step then needs one matrix-
// vector product u = A_b a + A_f p (N^2 multiply-adds over N^2 doubles), where a right-hand side
// and a back-substitution per step read 2 N^2 (docs/hydrodynamics.md, "Mixed boundary-value
// problem"). D_ij = 0 between two free-surface panels (coplanar).
#include <chrono>
#include <limits>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "forces/hydro/panel_geometry.hpp"

namespace yardsim::forces::hydro {

class MixedProblem {
 public:
  /// (body panels, free-surface panels, water depth h in m: infinity for deep water) => M, R_b,
  /// R_f assembled, M factorised and the solution map formed. Throws PanelError when h does not
  /// lie below the hull or M is singular.
  MixedProblem(std::vector<Panel> body, std::vector<Panel> freeSurface,
               double depth = std::numeric_limits<double>::infinity());
  /// Not copyable: the solution map is N x N doubles.
  MixedProblem(const MixedProblem&) = delete;
  MixedProblem& operator=(const MixedProblem&) = delete;

  /// (phi_n on the body, Nb x m; phi on the free surface, Nf x m) => u = [phi_b; phi_n,f], N x m,
  /// written into out (u = A_b a + A_f p). For a preallocated out nothing is allocated.
  void solve(const Eigen::Ref<const Eigen::MatrixXd>& bodyNormal,
             const Eigen::Ref<const Eigen::MatrixXd>& surfacePotential,
             Eigen::Ref<Eigen::MatrixXd> out) const;
  /// The same, allocating its result.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& bodyNormal,
                        const Eigen::MatrixXd& surfacePotential) const;

  /// (w, N x m: m functionals u => w^T u of the solution) => (w^T A_b, m x Nb; w^T A_f, m x Nf):
  /// the same functionals as maps of the data a, p (then a functional of the solution costs
  /// m (Nb + Nf) per step, not N^2).
  std::pair<Eigen::MatrixXd, Eigen::MatrixXd> adjointMaps(const Eigen::MatrixXd& w) const;

  /// The solution map A = M^-1 [R_b R_f], N x N: columns 0 .. Nb - 1 map a, the rest p. Its last
  /// Nf rows and columns are the map p => phi_n,f with the hull at rest (the growth check,
  /// surface_growth.hpp).
  const Eigen::MatrixXd& solutionMap() const { return map_; }

  int bodyCount() const { return static_cast<int>(body_.size()); }
  int surfaceCount() const { return static_cast<int>(surface_.size()); }
  int size() const { return bodyCount() + surfaceCount(); }
  const std::vector<Panel>& body() const { return body_; }
  const std::vector<Panel>& surface() const { return surface_; }
  double depth() const { return depth_; }
  /// Wall-clock seconds the influence assembly and the factorisation with the solution map took
  /// (measured in the constructor).
  double assemblySeconds() const { return assemblySeconds_; }
  double factorSeconds() const { return factorSeconds_; }

 private:
  std::vector<Panel> body_, surface_;
  double depth_;
  Eigen::MatrixXd map_;  ///< A = M^-1 [R_b R_f], N x N
  double assemblySeconds_ = 0.0, factorSeconds_ = 0.0;
};

}  // namespace yardsim::forces::hydro
