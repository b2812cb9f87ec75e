// yardsim's kernels (dynamics/aba, rnea, crba + the tree-sparse choleskyFactor) on a peer_models.hpp model.
#include <numeric>
#include <random>
#include <stdexcept>

#include "dynamics/aba.hpp"
#include "dynamics/crba.hpp"
#include "dynamics/tree_cholesky.hpp"
#include "dynamics/model_builder.hpp"
#include "dynamics/rnea.hpp"
#include "kernel.hpp"

namespace yardsim::bench::peers {

std::vector<BodySpec> modelSpec(const std::string& name, int n) {
  if (name == "chain" && n >= 1) return chain(n);
  if (name == "tree" && n >= 5) return tree(n);
  throw std::invalid_argument("model must be chain (N >= 1) or tree (N >= 5), got " + name + " " +
                              std::to_string(n));
}

NeutralState randomState(const std::vector<BodySpec>& spec, unsigned seed, bool rootAtRest) {
  NeutralState s;
  s.floating = !spec.empty() && spec[0].kind == JointKind::Free;
  const int nv = static_cast<int>(spec.size()) + (s.floating ? 5 : 0);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (Eigen::VectorXd* x : {&s.q, &s.v, &s.a, &s.tau}) {
    x->resize(nv);
    for (int i = 0; i < nv; ++i) (*x)[i] = u(rng);
  }
  if (s.floating) {
    s.q.head<6>().setZero();  // the root at the identity (its 6 entries are unused)
    if (rootAtRest) {
      s.v.head<6>().setZero();
      s.a.head<6>().setZero();
      s.tau.head<6>().setZero();
    }
  }
  return s;
}

namespace {

class YardsimKernel final : public Kernel {
 public:
  YardsimKernel(const std::vector<BodySpec>& spec, const NeutralState& s)
      : m_(build(spec)), d_(m_) {
    q_ = Eigen::VectorXd::Zero(m_.nq);
    v_.resize(m_.nv);
    a_.resize(m_.nv);
    tau_.resize(m_.nv);
    // (neutral order) => yardsim's velocity index of each neutral entry, and the coordinates
    int k = 0;
    for (std::size_t b = 0; b < spec.size(); ++b) {
      const int body = bodyIndex(static_cast<int>(b));
      if (spec[b].kind == JointKind::Free) {
        q_[m_.idxQ[body] + 3] = 1.0;  // quaternion w (the position and x, y, z stay 0)
        for (int j = 0; j < 6; ++j)
          vmap_.push_back(m_.idxV[body] + j);  // (omega, v) in the child frame
        k += 6;
      } else {
        q_[m_.idxQ[body]] = s.q[k];
        vmap_.push_back(m_.idxV[body]);
        ++k;
      }
    }
    for (int i = 0; i < m_.nv; ++i) {
      v_[vmap_[i]] = s.v[i];
      a_[vmap_[i]] = s.a[i];
      tau_[vmap_[i]] = s.tau[i];
    }
  }
  void aba() override { dynamics::aba(m_, d_, q_, v_, tau_); }
  void rnea() override { dynamics::rnea(m_, d_, q_, v_, a_); }
  void crbaChol() override {
    dynamics::crba(m_, d_, q_);
    dynamics::choleskyFactor(m_, d_);
  }
  Eigen::VectorXd tauNeutral() const override { return gather(d_.tau); }
  Eigen::VectorXd ddqNeutral() const override { return gather(d_.ddq); }
  Eigen::MatrixXd massNeutral() const override {
    Eigen::MatrixXd M(m_.nv, m_.nv);
    for (int i = 0; i < m_.nv; ++i)
      for (int j = 0; j < m_.nv; ++j) M(i, j) = d_.M(vmap_[i], vmap_[j]);
    return M;
  }

 private:
  static std::string name(int b) { return "b" + std::to_string(b); }
  int bodyIndex(int b) const {
    for (int i = 0; i < m_.nbodies; ++i)
      if (m_.names[i] == name(b)) return i;
    throw std::logic_error("body " + name(b) + " missing");
  }
  // (spec) => the yardsim model
  static dynamics::Model build(const std::vector<BodySpec>& spec) {
    using namespace dynamics;
    ModelBuilder mb;
    for (std::size_t b = 0; b < spec.size(); ++b) {
      const BodySpec& s = spec[b];
      const Vector3 axis = Vector3::Unit(s.axis);
      const Joint j = s.kind == JointKind::Free       ? Joint::free()
                      : s.kind == JointKind::Revolute ? Joint::revolute(axis)
                                                      : Joint::prismatic(axis);
      mb.addBody(name(static_cast<int>(b)), s.parent < 0 ? "world" : name(s.parent), j,
                 Transform::translation(s.offset),
                 makeInertia(s.mass, s.com, s.inertia.asDiagonal()));
    }
    return mb.build();
  }
  Eigen::VectorXd gather(const Eigen::VectorXd& x) const {
    Eigen::VectorXd r(m_.nv);
    for (int i = 0; i < m_.nv; ++i) r[i] = x[vmap_[i]];
    return r;
  }
  dynamics::Model m_;
  dynamics::Data d_;
  Eigen::VectorXd q_, v_, a_, tau_;
  std::vector<int> vmap_;
};

}  // namespace

std::unique_ptr<Kernel> makeYardsim(const std::vector<BodySpec>& spec, const NeutralState& s) {
  return std::make_unique<YardsimKernel>(spec, s);
}

}  // namespace yardsim::bench::peers
