// Pinocchio 3.7's kernels (aba, rnea, crba + its own sparse cholesky::decompose), header-only
// (no template instantiation library: every kernel compiled here, with this file's flags), on a
// peer_models.hpp model. ABA and CRBA in Pinocchio's LOCAL (default) or WORLD convention.
#include <pinocchio/algorithm/aba.hpp>
#include <pinocchio/algorithm/cholesky.hpp>
#include <pinocchio/algorithm/crba.hpp>
#include <pinocchio/algorithm/joint-configuration.hpp>
#include <pinocchio/algorithm/rnea.hpp>
#include <pinocchio/multibody/data.hpp>
#include <pinocchio/multibody/model.hpp>

#include "kernel.hpp"

namespace yardsim::bench::peers {
namespace {

namespace P = pinocchio;

// (kind, axis) => Pinocchio's special-cased joint model
P::JointModel jointModel(const BodySpec& s) {
  if (s.kind == JointKind::Free) return P::JointModelFreeFlyer();
  if (s.kind == JointKind::Revolute) {
    if (s.axis == 0) return P::JointModelRX();
    if (s.axis == 1) return P::JointModelRY();
    return P::JointModelRZ();
  }
  if (s.axis == 0) return P::JointModelPX();
  if (s.axis == 1) return P::JointModelPY();
  return P::JointModelPZ();
}

class PinocchioKernel final : public Kernel {
 public:
  PinocchioKernel(const std::vector<BodySpec>& spec, const NeutralState& s, bool world)
      : conv_(world ? P::Convention::WORLD : P::Convention::LOCAL) {
    m_.gravity.linear(Eigen::Vector3d(0.0, 0.0, -9.81));
    std::vector<P::JointIndex> id(spec.size());
    for (std::size_t b = 0; b < spec.size(); ++b) {
      const BodySpec& bs = spec[b];
      const P::SE3 X(Eigen::Matrix3d::Identity(), bs.offset);
      id[b] = m_.addJoint(bs.parent < 0 ? 0 : id[bs.parent], jointModel(bs), X,
                          "j" + std::to_string(b));
      const Eigen::Matrix3d I = bs.inertia.asDiagonal();
      m_.appendBodyToJoint(id[b], P::Inertia(bs.mass, bs.com, I), P::SE3::Identity());
    }
    d_ = P::Data(m_);
    q_ = P::neutral(m_);  // the free flyer's quaternion (x, y, z, w) = (0, 0, 0, 1)
    v_.resize(m_.nv);
    a_.resize(m_.nv);
    tau_.resize(m_.nv);
    // (neutral order) => Pinocchio's velocity index; a free flyer's v is (linear; angular), local
    int k = 0;
    for (std::size_t b = 0; b < spec.size(); ++b) {
      const int iv = m_.joints[id[b]].idx_v();
      if (spec[b].kind == JointKind::Free) {
        for (int j = 0; j < 3; ++j) vmap_.push_back(iv + 3 + j);
        for (int j = 0; j < 3; ++j) vmap_.push_back(iv + j);
        k += 6;
      } else {
        q_[m_.joints[id[b]].idx_q()] = s.q[k++];
        vmap_.push_back(iv);
      }
    }
    for (int i = 0; i < m_.nv; ++i) {
      v_[vmap_[i]] = s.v[i];
      a_[vmap_[i]] = s.a[i];
      tau_[vmap_[i]] = s.tau[i];
    }
  }
  void aba() override { P::aba(m_, d_, q_, v_, tau_, conv_); }
  void rnea() override { P::rnea(m_, d_, q_, v_, a_); }
  void crbaChol() override {
    P::crba(m_, d_, q_, conv_);
    P::cholesky::decompose(m_, d_);
  }
  Eigen::VectorXd tauNeutral() const override { return gather(d_.tau); }
  Eigen::VectorXd ddqNeutral() const override { return gather(d_.ddq); }
  Eigen::MatrixXd massNeutral() const override {
    Eigen::MatrixXd full = d_.M;
    full.triangularView<Eigen::StrictlyLower>() = full.transpose();
    Eigen::MatrixXd M(m_.nv, m_.nv);
    for (int i = 0; i < m_.nv; ++i)
      for (int j = 0; j < m_.nv; ++j) M(i, j) = full(vmap_[i], vmap_[j]);
    return M;
  }

 private:
  Eigen::VectorXd gather(const Eigen::VectorXd& x) const {
    Eigen::VectorXd r(m_.nv);
    for (int i = 0; i < m_.nv; ++i) r[i] = x[vmap_[i]];
    return r;
  }
  P::Convention conv_;
  P::Model m_;
  P::Data d_;
  Eigen::VectorXd q_, v_, a_, tau_;
  std::vector<int> vmap_;
};

}  // namespace

std::unique_ptr<Kernel> makePinocchio(const std::vector<BodySpec>& spec, const NeutralState& s,
                                      bool world) {
  return std::make_unique<PinocchioKernel>(spec, s, world);
}

}  // namespace yardsim::bench::peers
