#pragma once
// The Newton system (I - gamma J) x = b of a first-order solver (CVODE, ARKODE) on the chart
// state y = (theta, v) (chart_state.hpp), solved without a dense matrix for a system whose
// acceleration Jacobian has structure (lumped-mass lines: AccelerationSource::jacobianPattern).
// With theta' = G(theta) v (the chart's kinematics: the identity but for spherical and free
// joints) and v' = F(q, v), J = [K G; F_q F_v], K = d(G v)/d theta (block diagonal per rotational
// joint, zero elsewhere). Eliminating x_theta exactly, with P = (I - gamma K)^-1 and M = P G:
//   (I - gamma F_v - gamma^2 F_q M) x_v = b_v + gamma F_q P b_theta,
//   x_theta = P b_theta + gamma M x_v,
// whose matrix has F_q's pattern (M mixes only a joint's own columns) and is factorised by
// SparseNewtonMatrix (the bordered band LU for lines hanging from a few bodies: linear in the
// nodes, where the dense path is cubic). F_q, F_v come from coloured differences and the lines'
// closed-form blocks (sparse_newton_matrix.hpp), K and G per rotational joint from its chart
// rate. With the kinematics explicit (ARKODE's IMEX: J = [0 0; F_q F_v]), x_theta = b_theta and
// (I - gamma F_v) x_v = b_v + gamma F_q b_theta. F in 1/s^2 (per m, rad) and 1/s; gamma in s;
// x and b in y's units. Allocation-free after construction.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "dynamics/integrators/integrator.hpp"
#include "dynamics/integrators/sparse_newton_matrix.hpp"
#include "dynamics/model.hpp"

namespace yardsim::dynamics {

class ChartNewtonSystem {
 public:
  // (model, the source's pattern and closed-form blocks, whether theta' = G v is part of the
  // implicit right-hand side) => the sparse matrix on the pattern, each rotational joint's
  // columns given the same rows (the union of theirs)
  ChartNewtonSystem(const Model& model, const JacobianPattern& pattern,
                    const JacobianBlocks* blocks, bool kinematicImplicit = true);

  // (source, t, the chart origin q*, y = (theta, v), q = q* (+) theta, a = F(t, q, v)) =>
  // F_q (through the chart at q*), F_v, the lines' blocks, K and G; returns the evaluations
  int form(AccelerationSource& source, double t, const Eigen::VectorXd& origin, const double* y,
           const Eigen::VectorXd& q, const Eigen::VectorXd& a);
  // (source, t, q, v) => the closed-form blocks re-evaluated there (no evaluation of F)
  void refreshBlocks(AccelerationSource& source, double t, const Eigen::VectorXd& q,
                     const Eigen::VectorXd& v);
  // (gamma) => P, M and the LU of the reduced matrix; false when it is singular
  bool factorise(double gamma);
  // (b, size 2 nv) => x = (I - gamma J)^-1 b with the last factorisation's gamma (x may be b)
  void solve(const double* b, double* x);

  const SparseNewtonMatrix& matrix() const { return sparse_; }
  double gamma() const { return gamma_; }
  // the last factorise() succeeded
  bool factorised() const { return ok_; }

 private:
  struct Group {
    int joint = 0, first = 0, k = 0;      // the joint, its first dof, its dofs
    Eigen::Matrix<double, 6, 6> K, G, P;  // top-left k x k used
  };
  const Model& model_;
  bool kinematic_;
  std::vector<Group> groups_;
  std::vector<Eigen::Matrix<double, 6, 6>> maps_;  // M per group
  SparseNewtonMatrix sparse_;
  double gamma_ = 0.0;
  bool ok_ = false;
  Eigen::VectorXd theta_, v_, f_, u_, r_, xv_;
};

}  // namespace yardsim::dynamics
