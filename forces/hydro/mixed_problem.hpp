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
// LU-factorised once for the fixed geometry (Eigen partial-pivot LU, in place); every time step
// then needs the right-hand side (one pass over R_b and R_f, N^2 multiply-adds) and one
// back-substitution (2 N^2), for as many columns as it has cases. D_ij = 0 between two free-
// surface panels (coplanar).
#include <chrono>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/LU>

#include "forces/hydro/panel_geometry.hpp"

namespace yardsim::forces::hydro {

class MixedProblem {
 public:
  /// (body panels, free-surface panels, water depth h in m: infinity for deep water) => M, R_b,
  /// R_f assembled and M factorised. Throws PanelError when h does not lie below the hull.
  MixedProblem(std::vector<Panel> body, std::vector<Panel> freeSurface,
               double depth = std::numeric_limits<double>::infinity());
  /// Not copyable or movable: the LU factors refer to the matrix they overwrite.
  MixedProblem(const MixedProblem&) = delete;
  MixedProblem& operator=(const MixedProblem&) = delete;

  /// (phi_n on the body, Nb x m; phi on the free surface, Nf x m) => u = [phi_b; phi_n,f], N x m,
  /// written into out through rhs (N x m scratch). For preallocated rhs and out nothing is
  /// allocated but Eigen's packing blocks of the triangular solves, from the heap when larger than
  /// EIGEN_STACK_ALLOCATION_LIMIT (docs/performance.md, "Allocation-free steady state").
  void solve(const Eigen::Ref<const Eigen::MatrixXd>& bodyNormal,
             const Eigen::Ref<const Eigen::MatrixXd>& surfacePotential,
             Eigen::Ref<Eigen::MatrixXd> rhs, Eigen::Ref<Eigen::MatrixXd> out) const;
  /// The same, allocating its result.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& bodyNormal,
                        const Eigen::MatrixXd& surfacePotential) const;

  /// (w, N x m: m functionals u => w^T u of the solution) => (w^T M^-1 R_b, m x Nb; w^T M^-1 R_f,
  /// m x Nf): the same functionals as maps of the data a, p, through one transposed solve with the
  /// same factorisation (then a functional of the solution costs m (Nb + Nf) per step, not N^2).
  std::pair<Eigen::MatrixXd, Eigen::MatrixXd> adjointMaps(const Eigen::MatrixXd& w) const;

  /// (hull at rest, a = 0) => the N_f x N_f map p => phi_n,f: the last N_f rows of M^-1 R_f, for
  /// every free-surface column at once (the growth check, surface_growth.hpp). P R_f, then BLAS's
  /// DTRSM (OpenBLAS): the unit lower triangle over all N rows, and of the upper triangle only its
  /// trailing N_f x N_f block (the last rows of an upper-triangular solve need only its last rows).
  /// N^2 N_f + N_f^3 multiply-adds, where solve(0, I) would form R_f I and the whole back-
  /// substitution (three times as many). Allocates an N x N_f matrix.
  Eigen::MatrixXd surfaceMap() const;

  int bodyCount() const { return static_cast<int>(body_.size()); }
  int surfaceCount() const { return static_cast<int>(surface_.size()); }
  int size() const { return bodyCount() + surfaceCount(); }
  const std::vector<Panel>& body() const { return body_; }
  const std::vector<Panel>& surface() const { return surface_; }
  double depth() const { return depth_; }
  /// Wall-clock seconds the influence assembly and the LU took (measured in the constructor).
  double assemblySeconds() const { return assemblySeconds_; }
  double factorSeconds() const { return factorSeconds_; }

 private:
  std::vector<Panel> body_, surface_;
  double depth_;
  Eigen::MatrixXd system_;       ///< M, overwritten by its LU factors
  Eigen::MatrixXd fromBody_;     ///< R_b, N x Nb
  Eigen::MatrixXd fromSurface_;  ///< R_f, N x Nf
  std::optional<Eigen::PartialPivLU<Eigen::Ref<Eigen::MatrixXd>>> lu_;
  double assemblySeconds_ = 0.0, factorSeconds_ = 0.0;
};

}  // namespace yardsim::forces::hydro
