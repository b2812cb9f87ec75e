#pragma once
// One library's kernels on one model, behind one interface so that one timing loop serves all
// (a virtual call per kernel call: about 1 ns against 0.1-100 µs of work).
// The state is given neutrally: per body in spec order, the root's pose is the identity and
// its 6 velocities / accelerations / forces are given as (angular; linear) in the root frame;
// every 1-dof joint has one coordinate.
#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "peer_models.hpp"

namespace yardsim::bench::peers {

struct NeutralState {
  Eigen::VectorXd q, v, a, tau;  ///< 1-dof coordinates in spec order after the root's 6 (if any)
  bool floating = false;
};

// (spec, seed, root at rest?) => random 1-dof coordinates in [-1, 1], the root at the identity
NeutralState randomState(const std::vector<BodySpec>& spec, unsigned seed, bool rootAtRest);

class Kernel {
 public:
  virtual ~Kernel() = default;
  virtual void aba() = 0;       ///< forward dynamics
  virtual void rnea() = 0;      ///< inverse dynamics
  virtual void crbaChol() = 0;  ///< mass matrix and its Cholesky factor (the library's own, or
                                ///< Eigen's LLT in place)
  /// Results in the neutral order (root (angular; linear) first): after rnea, aba, crbaChol.
  virtual Eigen::VectorXd tauNeutral() const = 0;
  virtual Eigen::VectorXd ddqNeutral() const = 0;
  virtual Eigen::MatrixXd massNeutral() const = 0;
};

std::unique_ptr<Kernel> makeYardsim(const std::vector<BodySpec>& spec, const NeutralState& s);
#ifdef YARDSIM_PEERS_HAVE_RBDL
std::unique_ptr<Kernel> makeRbdl(const std::vector<BodySpec>& spec, const NeutralState& s);
#endif
#ifdef YARDSIM_PEERS_HAVE_PINOCCHIO
/// world: Pinocchio's Convention::WORLD for ABA and CRBA (LOCAL otherwise)
std::unique_ptr<Kernel> makePinocchio(const std::vector<BodySpec>& spec, const NeutralState& s,
                                      bool world);
#endif

}  // namespace yardsim::bench::peers
