#pragma once
// The multibody model as an AccelerationSource for the integrators: joint forces tau, external
// forces from an optional callback evaluated at every stage, ABA for a tree or the Schur-complement
// forward dynamics when the model has loops, with optional Baumgarte terms and post-step projection.

#include <functional>
#include <memory>
#include <stdexcept>

#include "dynamics/constrained_dynamics.hpp"
#include "dynamics/data.hpp"
#include "dynamics/external_forces.hpp"
#include "dynamics/hybrid_dynamics.hpp"
#include "dynamics/integrators/integrator.hpp"
#include "dynamics/model.hpp"

namespace yardsim::dynamics {

class MultibodySystem final : public AccelerationSource {
 public:
  /// (t, q, v, data after forward kinematics(q, v)) => forces to add, and tau (zeroed before the call).
  using ForceCallback = std::function<void(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Data& data,
                                           ExternalForces& forces, Eigen::VectorXd& tau)>;

  /// (t, q, v, data after forward kinematics(q, v)) => the signature of the switching forces'
  /// branches (AccelerationSource::regime).
  using RegimeCallback =
      std::function<std::uint64_t(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Data& data)>;

  explicit MultibodySystem(const Model& model);

  void setForces(ForceCallback callback) { callback_ = std::move(callback); }
  /// Set when a force of the callback switches (a contact): switches() is then true.
  void setRegime(RegimeCallback callback) { regime_ = std::move(callback); }
  void setBaumgarte(const Baumgarte& stab) { stab_ = stab; }
  /// Project positions (to tol) and velocities onto the loop manifold after every step.
  void setProjection(bool on, double tol = 1e-12) {
    project_ = on;
    projectTol_ = tol;
  }

  /// (t, q, v) => a; throws IntegrationError naming the first body whose state or acceleration is
  /// not finite.
  void acceleration(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::VectorXd& a) override;
  void afterStep(double t, Eigen::VectorXd& q, Eigen::VectorXd& v) override;
  int constraintRows() const override { return model_.nc; }
  bool switches() const override { return static_cast<bool>(regime_); }
  /// (t, q, v) => the regime callback after forward kinematics (0 without one).
  std::uint64_t regime(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v) override;
  /// (t, q, v) => ABA on the tree with the same forces, without the loops' forces.
  void unconstrainedAcceleration(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                 Eigen::VectorXd& a) override;
  void constraintTerms(const Eigen::VectorXd& q, Eigen::VectorXd& g, Eigen::MatrixXd& J,
                       Eigen::MatrixXd& MinvJt) override;

  /// The structure of the accelerations' Jacobian that the force callback promises (nullptr:
  /// dense, the default); the implicit integrators use it for a sparse Newton matrix.
  void setJacobianPattern(std::shared_ptr<const JacobianPattern> p) { pattern_ = std::move(p); }
  const JacobianPattern* jacobianPattern() const override { return pattern_.get(); }
  /// (t, q, v, data after forward kinematics(q, v), d a/dq, d a/dv) => the blocks' values and
  /// the switch signature (AccelerationSource::blockJacobian).
  using BlockCallback = std::function<std::uint64_t(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                                    const Data& data, std::vector<Eigen::Matrix3d>& dq,
                                                    std::vector<Eigen::Matrix3d>& dv)>;
  /// The blocks of the Jacobian the callback gives in closed form (nullptr: none).
  void setJacobianBlocks(std::shared_ptr<const JacobianBlocks> b, BlockCallback callback) {
    blocks_ = std::move(b);
    blockCallback_ = std::move(callback);
  }
  const JacobianBlocks* jacobianBlocks() const override { return pattern_ ? blocks_.get() : nullptr; }
  std::uint64_t blockJacobian(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                              std::vector<Eigen::Matrix3d>& dq, std::vector<Eigen::Matrix3d>& dv) override;

  /// (on, t, q, v, data after forward kinematics(q, v)) => the callback's forces linearised
  /// about (t, q, v) from on = true until on = false (AccelerationSource::beginLinearisation).
  using LinearisationCallback = std::function<void(bool on, double t, const Eigen::VectorXd& q,
                                                   const Eigen::VectorXd& v, const Data& data)>;
  void setLinearisation(LinearisationCallback callback) { linearisation_ = std::move(callback); }
  void beginLinearisation(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v) override;
  void endLinearisation() override;
  bool linearises() const override { return static_cast<bool>(linearisation_); }

  /// Prescribed motion (trees only): the dofs flagged in mask move with the accelerations in
  /// aPrescribed (others ignored) instead of responding to forces; the force callback may call
  /// this at every stage. The joint forces that enforce them: prescribedEffort().
  void prescribe(const std::vector<char>& mask, const Eigen::VectorXd& aPrescribed);
  const Eigen::VectorXd& prescribedEffort() const { return effort_; }
  HybridDynamics& hybrid() { return hybrid_; }

  const Model& model() const { return model_; }
  Data& data() { return data_; }
  /// The external forces of the last stage evaluated (acceleration() or
  /// unconstrainedAcceleration()): nullptr when it had none. Valid until the next evaluation.
  const ExternalForces* stageExternalForces() const { return forces_.empty() ? nullptr : &forces_; }

  /// One stage kept for a caller that reads the same stage later (a step's first stage, read again
  /// at the committed state for the joint reactions): its t, q, v, accelerations and forces.
  struct KeptStage {
    explicit KeptStage(const Model& m) : q(m.nq), v(m.nv), a(m.nv), forces(m) {}
    bool valid = false;  // false: nothing kept since keepNextStage()
    double t = 0.0;      // s
    Eigen::VectorXd q, v, a;
    ExternalForces forces;  // the stage's external forces (empty: it had none)
  };
  /// () => the kept stage is dropped, and the next acceleration() (not while linearised) is kept
  /// in it; allocation-free. stopKeeping(): no later evaluation is kept.
  void keepNextStage() {
    kept_.valid = false;
    keep_ = true;
  }
  void stopKeeping() { keep_ = false; }
  void dropKeptStage() { kept_.valid = false; }
  const KeptStage& keptStage() const { return kept_; }
  Eigen::VectorXd& tau() { return tau_; }  ///< constant joint forces used when no callback is set

 private:
  const Model& model_;
  Data data_;
  ExternalForces forces_;
  Eigen::VectorXd tau_, tauStage_;
  HybridDynamics hybrid_;
  Eigen::VectorXd aPrescribed_, effort_;
  ForceCallback callback_;
  RegimeCallback regime_;
  std::shared_ptr<const JacobianPattern> pattern_;
  std::shared_ptr<const JacobianBlocks> blocks_;
  BlockCallback blockCallback_;
  LinearisationCallback linearisation_;
  bool linearised_ = false;
  bool keep_ = false;  // the next acceleration() is kept in kept_
  KeptStage kept_;
  // (t, q, v) => forces_ and tauStage_ from tau_ and the callback; refuses a non-finite state
  const ExternalForces* stageForces(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v);
  Baumgarte stab_;
  bool project_ = false;
  double projectTol_ = 1e-12;
};

}  // namespace yardsim::dynamics
