#include "dynamics/multibody_system.hpp"

#include "dynamics/aba.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/projection.hpp"

namespace yardsim::dynamics {

MultibodySystem::MultibodySystem(const Model& model)
    : model_(model),
      data_(model),
      scratch_(model),
      forces_(model),
      tau_(Eigen::VectorXd::Zero(model.nv)),
      tauStage_(Eigen::VectorXd::Zero(model.nv)) {}

void MultibodySystem::acceleration(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::VectorXd& a) {
  // (t, q, v) => forces from the callback (with kinematics available in scratch)
  forces_.clear();
  tauStage_ = tau_;
  if (callback_) {
    forwardKinematics(model_, scratch_, q, v);
    callback_(t, q, v, scratch_, forces_, tauStage_);
  }
  const ExternalForces* f = forces_.empty() ? nullptr : &forces_;
  // (q, v, tau, f) => ddq by ABA (tree) or with loop multipliers
  if (model_.nc == 0) {
    a = aba(model_, data_, q, v, tauStage_, f);
  } else {
    a = constrainedForwardDynamics(model_, data_, q, v, tauStage_, f, stab_);
  }
}

void MultibodySystem::afterStep(double, Eigen::VectorXd& q, Eigen::VectorXd& v) {
  if (!project_ || model_.nc == 0) return;
  projectPositions(model_, data_, q, projectTol_);
  projectVelocities(model_, data_, q, v);
}

}  // namespace yardsim::dynamics
