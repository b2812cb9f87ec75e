#include "dynamics/hybrid_dynamics.hpp"

#include "dynamics/crba.hpp"
#include "dynamics/rnea.hpp"
#include "dynamics/tree_cholesky.hpp"

namespace yardsim::dynamics {

HybridDynamics::HybridDynamics(const Model& model)
    : model_(model),
      Mff_(model.nv, model.nv),
      Mfp_(model.nv, model.nv),
      Lff_(Eigen::MatrixXd::Zero(model.nv, model.nv)),
      rhs_(model.nv),
      af_(model.nv),
      ap_(model.nv),
      work_(model.nv) {
  const auto nv = static_cast<std::size_t>(model.nv);
  free_.reserve(nv);
  fixed_.reserve(nv);
  freeParent_.reserve(nv);
  freeSubtree_.reserve(nv);
  position_.reserve(nv);
}

void HybridDynamics::setPrescribed(const std::vector<char>& prescribed) {
  free_.clear();
  fixed_.clear();
  for (int k = 0; k < model_.nv; ++k) (prescribed[static_cast<std::size_t>(k)] ? fixed_ : free_).push_back(k);
  np_ = static_cast<Eigen::Index>(fixed_.size());
  // (free dofs) => the induced tree: a free dof's parent is its nearest free ancestor, its subtree
  // the free dofs of its subtree (contiguous, since the order is kept)
  position_.assign(static_cast<std::size_t>(model_.nv), -1);
  for (std::size_t f = 0; f < free_.size(); ++f)
    position_[static_cast<std::size_t>(free_[f])] = static_cast<int>(f);
  freeParent_.clear();
  freeSubtree_.clear();
  for (std::size_t f = 0; f < free_.size(); ++f) {
    const int k = free_[f];
    int p = model_.dofParent[static_cast<std::size_t>(k)];
    while (p >= 0 && position_[static_cast<std::size_t>(p)] < 0)
      p = model_.dofParent[static_cast<std::size_t>(p)];
    freeParent_.push_back(p >= 0 ? position_[static_cast<std::size_t>(p)] : -1);
    const int end = k + model_.dofSubtree[static_cast<std::size_t>(k)];
    int count = 0;
    for (std::size_t g = f; g < free_.size() && free_[g] < end; ++g) ++count;
    freeSubtree_.push_back(count);
  }
}

void HybridDynamics::factorFree(Data& data, const Eigen::VectorXd& q) {
  // (q) => M, then its free-free block factored and the free-prescribed block
  const Eigen::MatrixXd& M = crba(model_, data, q);
  const auto nf = static_cast<Eigen::Index>(free_.size());
  Mff_.resize(nf, nf);
  Mfp_.resize(nf, np_);
  for (Eigen::Index i = 0; i < nf; ++i) {
    for (Eigen::Index j = 0; j < nf; ++j) Mff_(i, j) = M(free_[i], free_[j]);
    for (Eigen::Index j = 0; j < np_; ++j) Mfp_(i, j) = M(free_[i], fixed_[j]);
  }
  treeCholeskyFactor(Mff_, freeParent_, freeSubtree_, Lff_.topLeftCorner(nf, nf), work_);
}

void HybridDynamics::compute(Data& data, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                             const Eigen::VectorXd& tau, const ExternalForces* fext, Eigen::VectorXd& a,
                             Eigen::VectorXd& effort) {
  const auto nf = static_cast<Eigen::Index>(free_.size());
  // (q, v, fext) => h - J^T F_ext; (q) => M partitioned
  const Eigen::VectorXd& h = biasForces(model_, data, q, v, fext);
  factorFree(data, q);
  const Eigen::MatrixXd& M = data.M;
  // (prescribed a_p) => free accelerations
  ap_.resize(np_);
  for (Eigen::Index j = 0; j < np_; ++j) ap_[j] = a[fixed_[j]];
  rhs_.resize(nf);
  for (Eigen::Index i = 0; i < nf; ++i) rhs_[i] = tau[free_[i]] - h[free_[i]];
  rhs_.noalias() -= Mfp_ * ap_;
  af_.resize(nf);
  af_ = rhs_;
  treeCholeskySolveInPlace(Lff_.topLeftCorner(nf, nf), freeSubtree_, af_);
  for (Eigen::Index i = 0; i < nf; ++i) a[free_[i]] = af_[i];
  // (a) => the effort on the prescribed dofs
  effort.setZero();
  for (Eigen::Index j = 0; j < np_; ++j) {
    const int r = fixed_[j];
    effort[r] = M.row(r).dot(a) + h[r] - tau[r];
  }
}

void HybridDynamics::velocityStep(Data& data, const Eigen::VectorXd& q, Eigen::VectorXd& v, const Eigen::VectorXd& dv) {
  const auto nf = static_cast<Eigen::Index>(free_.size());
  factorFree(data, q);
  // (dv_p) => dv_f = -M_ff^-1 M_fp dv_p
  ap_.resize(np_);
  for (Eigen::Index j = 0; j < np_; ++j) ap_[j] = dv[fixed_[j]];
  rhs_.resize(nf);
  rhs_.noalias() = -Mfp_ * ap_;
  af_.resize(nf);
  af_ = rhs_;
  treeCholeskySolveInPlace(Lff_.topLeftCorner(nf, nf), freeSubtree_, af_);
  for (Eigen::Index i = 0; i < nf; ++i) v[free_[i]] += af_[i];
  for (Eigen::Index j = 0; j < np_; ++j) v[fixed_[j]] += ap_[j];
}

}  // namespace yardsim::dynamics
