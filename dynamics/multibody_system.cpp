#include "dynamics/multibody_system.hpp"

#include <cmath>
#include <sstream>

#include "dynamics/aba.hpp"
#include "dynamics/crba.hpp"
#include "dynamics/loop_constraints.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/projection.hpp"
#include "dynamics/tree_cholesky.hpp"

namespace yardsim::dynamics {

MultibodySystem::MultibodySystem(const Model& model)
    : model_(model),
      data_(model),
      forces_(model),
      tau_(Eigen::VectorXd::Zero(model.nv)),
      tauStage_(Eigen::VectorXd::Zero(model.nv)),
      hybrid_(model),
      aPrescribed_(Eigen::VectorXd::Zero(model.nv)),
      effort_(Eigen::VectorXd::Zero(model.nv)),
      kept_(model) {}

void MultibodySystem::prescribe(const std::vector<char>& mask, const Eigen::VectorXd& aPrescribed) {
  hybrid_.setPrescribed(mask);
  aPrescribed_ = aPrescribed;
}

namespace {
// (what, body, t) => a diagnosis naming the body, with a suggestion
[[noreturn]] void diverged(const Model& m, double t, const char* what, int body) {
  std::ostringstream s;
  s << "yardsim::dynamics: " << what << " of body '" << m.names[body] << "' is not finite at t = " << t
    << " s; the integration has diverged: try a smaller step, or an implicit integrator for stiff forces";
  throw IntegrationError(s.str());
}

// (x) => whether every entry is finite: x 0 is 0 for a finite entry and NaN for an infinite or NaN
// one, and their sum is one vectorised pass without branches (Eigen's allFinite tests entry by
// entry: at every integrator stage on q, v and a)
bool finite(const Eigen::VectorXd& x) {
  return (x.array() * 0.0).sum() == 0.0;
}

int firstNonFinite(const Eigen::VectorXd& x) {
  for (int k = 0; k < x.size(); ++k) {
    if (!std::isfinite(x[k])) return k;
  }
  return -1;
}
}  // namespace

const ExternalForces* MultibodySystem::stageForces(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
  // (q, v) => refuse a state that has already diverged
  if (!finite(q) || !finite(v)) {
    for (int i = 1; i < model_.nbodies; ++i) {
      if (!q.segment(model_.idxQ[i], model_.jointNq[i]).allFinite()) diverged(model_, t, "the configuration", i);
      if (!v.segment(model_.idxV[i], model_.jointNv[i]).allFinite()) diverged(model_, t, "the velocity", i);
    }
  }
  // (t, q, v) => forces from the callback, with the stage's kinematics in data_ (ABA reuses them)
  forces_.clear();
  tauStage_ = tau_;
  if (callback_) {
    forwardKinematics(model_, data_, q, v);
    callback_(t, q, v, data_, forces_, tauStage_);
  }
  return forces_.empty() ? nullptr : &forces_;
}

void MultibodySystem::acceleration(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::VectorXd& a) {
  const ExternalForces* f = stageForces(t, q, v);
  // (q, v, tau, f) => ddq by hybrid dynamics (prescribed dofs), ABA (tree) or with loop multipliers
  if (hybrid_.any()) {
    if (model_.nc > 0) throw IntegrationError("yardsim::dynamics: prescribed motion needs a tree (no loop closures)");
    a = aPrescribed_;
    hybrid_.compute(data_, q, v, tauStage_, f, a, effort_);
  } else if (model_.nc == 0) {
    a = callback_ ? abaAfterKinematics(model_, data_, q, v, tauStage_, f) : aba(model_, data_, q, v, tauStage_, f);
  } else {
    a = constrainedForwardDynamics(model_, data_, q, v, tauStage_, f, stab_);
  }
  // (a) => the body whose acceleration is not finite, if any
  if (!finite(a)) diverged(model_, t, "the acceleration", model_.dofBody[firstNonFinite(a)]);
  // (asked to keep this stage, not linearised) => its state, accelerations and forces copied
  if (keep_) {
    keep_ = false;
    if (linearised_) return;
    kept_.t = t;
    kept_.q = q;
    kept_.v = v;
    kept_.a = a;
    kept_.forces = forces_;
    kept_.valid = true;
  }
}

std::uint64_t MultibodySystem::regime(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
  if (!regime_) return 0;
  forwardKinematics(model_, data_, q, v);
  return regime_(t, q, v, data_);
}

void MultibodySystem::unconstrainedAcceleration(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                                Eigen::VectorXd& a) {
  const ExternalForces* f = stageForces(t, q, v);
  if (hybrid_.any()) {  // (prescribed dofs) => hybrid dynamics, as in acceleration()
    a = aPrescribed_;
    hybrid_.compute(data_, q, v, tauStage_, f, a, effort_);
  } else {
    a = callback_ ? abaAfterKinematics(model_, data_, q, v, tauStage_, f) : aba(model_, data_, q, v, tauStage_, f);
  }
  if (!finite(a)) diverged(model_, t, "the acceleration", model_.dofBody[firstNonFinite(a)]);
}

void MultibodySystem::constraintTerms(const Eigen::VectorXd& q, Eigen::VectorXd& g, Eigen::MatrixXd& J,
                                      Eigen::MatrixXd& MinvJt) {
  // (q) => g(q), J(q), M^-1 J^T by CRBA + Cholesky
  g = loopResidual(model_, data_, q);
  J = loopJacobian(model_, data_, q);
  crba(model_, data_, q);
  choleskyFactor(model_, data_);
  MinvJt = J.transpose();
  choleskySolveInPlace(model_, data_, MinvJt);
}

void MultibodySystem::afterStep(double, Eigen::VectorXd& q, Eigen::VectorXd& v) {
  if (!project_ || model_.nc == 0) return;
  projectPositions(model_, data_, q, projectTol_);
  projectVelocities(model_, data_, q, v);
}

std::uint64_t MultibodySystem::blockJacobian(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                             std::vector<Eigen::Matrix3d>& dq, std::vector<Eigen::Matrix3d>& dv) {
  // (q, v) => kinematics in data_ (the next stage recomputes them), then the callback's blocks
  if (!blockCallback_) return 0;
  forwardKinematics(model_, data_, q, v);
  return blockCallback_(t, q, v, data_, dq, dv);
}

void MultibodySystem::beginLinearisation(double t, const Eigen::VectorXd& q,
                                         const Eigen::VectorXd& v) {
  // (q, v) => kinematics in data_ (the next stage recomputes them), then the callback's
  // linearisation there; a scope already open is ended first, and one that throws is ended
  if (!linearisation_) return;
  endLinearisation();
  forwardKinematics(model_, data_, q, v);
  linearised_ = true;
  try {
    linearisation_(true, t, q, v, data_);
  } catch (...) {
    endLinearisation();
    throw;
  }
}

void MultibodySystem::endLinearisation() {
  if (!linearised_) return;
  linearised_ = false;
  linearisation_(false, 0.0, Eigen::VectorXd(), Eigen::VectorXd(), data_);
}

}  // namespace yardsim::dynamics
