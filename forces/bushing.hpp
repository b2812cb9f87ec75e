#pragma once
// A 6-dof bushing between frame F fixed on body A and frame G fixed on body B (either body may
// be the world, 0). Its displacement, in F, is delta = [theta; d]: theta = log(R_FG), the
// rotation vector of G relative to F (rad), and d = p_FG, the origin of G in F (m); its rate
// delta' = [J_r^{-1}(theta) w_FG_G; d/dt p_FG]. With 6x6 stiffness K and damping C, ordered
// [angular; linear] like every spatial quantity here (N m/rad, N/m and their couplings; C in
// the same units times s), the generalized force Q = K delta + C delta' acts as the wrench
//   moment  -R_WG J_r^{-T}(theta) Q_rot   and force  -R_WF Q_lin   on B at G's origin,
// and the opposite wrench on A at the same point (equal and opposite, world frame). For small
// rotations this is the linear bushing -K delta; for large ones it stays exactly conservative:
// V = 1/2 delta^T K delta, J (K symmetric), and power -delta'^T C delta' <= 0, W (C symmetric
// positive semidefinite).
#include <string>

#include "forces/force_provider.hpp"

namespace yardsim::forces {

struct BushingProperties {
  dynamics::Matrix6 stiffness = dynamics::Matrix6::Zero();  // K, symmetric, [angular; linear]
  dynamics::Matrix6 damping = dynamics::Matrix6::Zero();    // C, symmetric, >= 0
};

// The bushing at one stage: delta and delta' in F (see above), and Q = K delta + C delta'.
struct BushingState {
  dynamics::Vector6 displacement = dynamics::Vector6::Zero();
  dynamics::Vector6 rate = dynamics::Vector6::Zero();
  dynamics::Vector6 generalizedForce = dynamics::Vector6::Zero();
};

class Bushing final : public ForceProvider {
 public:
  // (name, model, body A, X_AF, body B, X_BG, properties) => the element; throws
  // std::invalid_argument naming it for a body outside the model, a non-finite frame, a K or C
  // that is not symmetric, or a C with a negative eigenvalue
  Bushing(std::string name, const dynamics::Model& model, int bodyA,
          const dynamics::Transform& X_AF, int bodyB, const dynamics::Transform& X_BG,
          const BushingProperties& properties);

  // (stage) => delta, delta' and Q
  BushingState state(const Stage& s) const;
  const BushingProperties& properties() const { return p_; }

 protected:
  void doEvaluate(const Stage& s, dynamics::ExternalForces& f, Eigen::VectorXd& tau) const override;
  double doPotentialEnergy(const Stage& s) const override;
  double doPower(const Stage& s) const override;

 private:
  // (stage) => the state with X_WF, X_WG and J_r^{-1}(theta)
  struct Frames {
    dynamics::Transform X_WF, X_WG;
    dynamics::Matrix3 JrInv;
    BushingState st;
  };
  Frames frames(const Stage& s) const;

  int bodyA_, bodyB_;
  dynamics::Transform X_AF_, X_BG_;
  BushingProperties p_;
};

}  // namespace yardsim::forces
