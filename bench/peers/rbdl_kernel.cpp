// RBDL 3.3's kernels (ForwardDynamics, InverseDynamics, CompositeRigidBodyAlgorithm + Eigen's LLT
// into preallocated storage; RBDL has no Cholesky of its own) on a peer_models.hpp model.
// A revolute joint about a unit axis becomes RBDL's special-cased RevoluteX/Y/Z.
#include <rbdl/rbdl.h>
#include <Eigen/Cholesky>

#include "kernel.hpp"

namespace yardsim::bench::peers {
namespace {

namespace R = RigidBodyDynamics;
using R::Math::SpatialVector;
using R::Math::Vector3d;

class RbdlKernel final : public Kernel {
 public:
  RbdlKernel(const std::vector<BodySpec>& spec, const NeutralState& s) {
    m_.gravity = Vector3d(0.0, 0.0, -9.81);
    std::vector<unsigned> id(spec.size());
    for (std::size_t b = 0; b < spec.size(); ++b) {
      const BodySpec& bs = spec[b];
      SpatialVector axis = SpatialVector::Zero();
      axis[(bs.kind == JointKind::Prismatic ? 3 : 0) + bs.axis] = 1.0;
      const R::Joint joint =
          bs.kind == JointKind::Free ? R::Joint(R::JointTypeFloatingBase) : R::Joint(axis);
      const R::Math::Matrix3d I(Eigen::Matrix3d(bs.inertia.asDiagonal()));
      id[b] = m_.AddBody(bs.parent < 0 ? 0 : id[bs.parent], R::Math::Xtrans(bs.offset), joint,
                         R::Body(bs.mass, bs.com, I));
    }
    const int n = static_cast<int>(m_.dof_count);
    q_ = R::Math::VectorNd::Zero(m_.q_size);
    v_.resize(n);
    a_.resize(n);
    tau_.resize(n);
    ddq_ = R::Math::VectorNd::Zero(n);
    rneaOut_ = R::Math::VectorNd::Zero(n);
    H_ = R::Math::MatrixNd::Zero(n, n);  // CRBA writes only the ancestor pairs; the rest stays 0
    llt_ = Eigen::LLT<Eigen::MatrixXd>(n);
    // (neutral order) => RBDL's dof index: a floating base is a translation (linear velocity in the
    // parent frame) then a spherical joint (angular velocity in the body frame)
    int k = 0;
    for (std::size_t b = 0; b < spec.size(); ++b) {
      const int qi = static_cast<int>(m_.mJoints[id[b]].q_index);
      if (spec[b].kind == JointKind::Free) {
        m_.SetQuaternion(id[b], R::Math::Quaternion(0.0, 0.0, 0.0, 1.0), q_);
        for (int j = 0; j < 3; ++j) vmap_.push_back(qi + j);      // angular
        for (int j = 0; j < 3; ++j) vmap_.push_back(qi - 3 + j);  // linear (the translation joint)
        k += 6;
      } else {
        q_[qi] = s.q[k++];
        vmap_.push_back(qi);
      }
    }
    for (int i = 0; i < n; ++i) {
      v_[vmap_[i]] = s.v[i];
      a_[vmap_[i]] = s.a[i];
      tau_[vmap_[i]] = s.tau[i];
    }
  }
  void aba() override { R::ForwardDynamics(m_, q_, v_, tau_, ddq_); }
  void rnea() override { R::InverseDynamics(m_, q_, v_, a_, rneaOut_); }
  void crbaChol() override {
    R::CompositeRigidBodyAlgorithm(m_, q_, H_, true);
    llt_.compute(H_);
  }
  Eigen::VectorXd tauNeutral() const override { return gather(rneaOut_); }
  Eigen::VectorXd ddqNeutral() const override { return gather(ddq_); }
  Eigen::MatrixXd massNeutral() const override {
    const int n = static_cast<int>(vmap_.size());
    Eigen::MatrixXd M(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) M(i, j) = H_(vmap_[i], vmap_[j]);
    return M;
  }

 private:
  Eigen::VectorXd gather(const R::Math::VectorNd& x) const {
    Eigen::VectorXd r(static_cast<int>(vmap_.size()));
    for (int i = 0; i < r.size(); ++i) r[i] = x[vmap_[i]];
    return r;
  }
  R::Model m_;
  R::Math::VectorNd q_, v_, a_, tau_, ddq_, rneaOut_;
  R::Math::MatrixNd H_;
  Eigen::LLT<Eigen::MatrixXd> llt_;
  std::vector<int> vmap_;
};

}  // namespace

std::unique_ptr<Kernel> makeRbdl(const std::vector<BodySpec>& spec, const NeutralState& s) {
  return std::make_unique<RbdlKernel>(spec, s);
}

}  // namespace yardsim::bench::peers
