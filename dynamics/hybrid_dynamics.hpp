#pragma once
// Hybrid dynamics (Featherstone 2008, §9.2): some degrees of freedom have their motion
// prescribed (acceleration given), the others are free (force given). With the joint-space mass
// matrix M (CRBA) and the bias forces h (RNEA with the external forces), partitioned into free
// (f) and prescribed (p) rows:
//   M_ff a_f = tau_f - h_f - M_fp a_p          (the free accelerations)
//   e_p      = M_pf a_f + M_pp a_p + h_p - tau_p (the effort that enforces the prescribed motion)
// A velocity step imposed on the prescribed dofs moves the free ones by the impulse response
// dv_f = -M_ff^-1 M_fp dv_p. M_ff keeps the tree's sparsity (a free dof's parent is its nearest
// free ancestor), so it is factorised along that induced tree (tree_cholesky.hpp). Trees only (no
// loop closures). Allocation-free after construction.

#include <Eigen/Core>
#include <vector>

#include "dynamics/data.hpp"
#include "dynamics/external_forces.hpp"
#include "dynamics/model.hpp"

namespace yardsim::dynamics {

class HybridDynamics {
 public:
  explicit HybridDynamics(const Model& model);

  /// (prescribed mask per dof) => the partition used by the calls below (allocation-free when
  /// the number of prescribed dofs does not grow beyond what was seen before).
  void setPrescribed(const std::vector<char>& prescribed);
  bool any() const { return np_ > 0; }

  /// (q, v, tau, fext, a with the prescribed dofs' accelerations) => a with the free ones too;
  /// effort (size nv) holds e_p on the prescribed dofs and 0 elsewhere.
  void compute(Data& data, const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Eigen::VectorXd& tau,
               const ExternalForces* fext, Eigen::VectorXd& a, Eigen::VectorXd& effort);

  /// (q, v, dv_p on the prescribed dofs of dv) => v + dv with the free dofs' impulse response.
  void velocityStep(Data& data, const Eigen::VectorXd& q, Eigen::VectorXd& v, const Eigen::VectorXd& dv);

 private:
  void factorFree(Data& data, const Eigen::VectorXd& q);

  const Model& model_;
  std::vector<int> free_, fixed_;  // dof indices: free, prescribed
  std::vector<int> freeParent_, freeSubtree_;  // the dof tree induced on the free dofs
  std::vector<int> position_;                  // per dof: its index among the free dofs, or -1
  Eigen::Index np_ = 0;
  Eigen::MatrixXd Mff_, Mfp_;
  Eigen::MatrixXd Lff_;  // M_ff = L^T L
  Eigen::VectorXd rhs_, af_, ap_, work_;
};

}  // namespace yardsim::dynamics
