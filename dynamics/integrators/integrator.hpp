#pragma once
// The interface between a second-order system on the configuration manifold and an integrator.
// The state is (q, v); dq/dt follows v through the joints' integrate() (configuration.hpp), so
// quaternions stay unit length whatever the method. Index-3 methods (HHT, generalized-alpha) also
// use the loop-constraint terms; adaptive methods (SUNDIALS) may locate state events.

#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <vector>
#include <stdexcept>
#include <string_view>

#include "dynamics/integrators/column_colouring.hpp"

namespace yardsim::dynamics {

/// Thrown when the state or the accelerations stop being finite (the message names the body), or
/// an implicit method's Newton iteration fails.
class IntegrationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// dv/dt = a(t, q, v), plus an optional hook after every accepted step (projection, events).
class AccelerationSource {
 public:
  virtual ~AccelerationSource() = default;
  /// (t, q, v) => a (size nv, preallocated by the caller).
  virtual void acceleration(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::VectorXd& a) = 0;
  /// Called with the new state after each step; may change it (e.g. constraint projection).
  virtual void afterStep(double /*t*/, Eigen::VectorXd& /*q*/, Eigen::VectorXd& /*v*/) {}

  /// Number of loop-constraint rows g(q) = 0 (0: an ODE, the default).
  virtual int constraintRows() const { return 0; }
  /// (t, q, v) => the accelerations of the tree without the loop constraints' forces (size nv).
  virtual void unconstrainedAcceleration(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                         Eigen::VectorXd& a) {
    acceleration(t, q, v, a);
  }
  /// (q) => g(q) (rows), J = dg/dq (rows x nv) and M^-1 J^T (nv x rows); only when rows > 0.
  virtual void constraintTerms(const Eigen::VectorXd& /*q*/, Eigen::VectorXd& /*g*/, Eigen::MatrixXd& /*J*/,
                               Eigen::MatrixXd& /*MinvJt*/) {}

  /// The structure of d a / d(q, v) when the source knows it (lumped-mass lines), or nullptr
  /// (the default: dense). Implicit methods then form and factorise a sparse Newton matrix.
  virtual const JacobianPattern* jacobianPattern() const { return nullptr; }
  /// The blocks of the Jacobian known in closed form (with a pattern only), or nullptr.
  virtual const JacobianBlocks* jacobianBlocks() const { return nullptr; }
  /// (t, q, v) => the values of jacobianBlocks()' blocks, d a/d q (1/s^2) and d a/d v (1/s), in
  /// its order; returns a signature of the force laws' switches (slack or taut, contact) that
  /// changes when one switches.
  virtual std::uint64_t blockJacobian(double /*t*/, const Eigen::VectorXd& /*q*/, const Eigen::VectorXd& /*v*/,
                                      std::vector<Eigen::Matrix3d>& /*dq*/, std::vector<Eigen::Matrix3d>& /*dv*/) {
    return 0;
  }

  /// Whether some force of the source switches between branches of its law (a contact closing or
  /// opening) that regime() tells apart; false (the default): regime() is never asked.
  virtual bool switches() const { return false; }
  /// (t, q, v) => a signature of the switching forces' branches at this state: two states with
  /// the same signature have the same forces on (the implicit methods sub-step a step whose start
  /// and end differ, docs/integrators.md "Switching forces").
  virtual std::uint64_t regime(double /*t*/, const Eigen::VectorXd& /*q*/, const Eigen::VectorXd& /*v*/) { return 0; }

  /// Finite-difference Jacobians (the implicit methods' Newton matrices, the stiffness estimate):
  /// (t, q, v) => until endLinearisation(), the source evaluates the forces that have an analytic
  /// linearisation (a quasi-static catenary line) as that linearisation about (t, q, v): exact
  /// derivatives there and no inner solve per column; the value at (t, q, v) itself is unchanged.
  virtual void beginLinearisation(double /*t*/, const Eigen::VectorXd& /*q*/,
                                  const Eigen::VectorXd& /*v*/) {}
  virtual void endLinearisation() {}
  /// Whether some force of the source has such a linearisation (false: the calls do nothing).
  virtual bool linearises() const { return false; }

  /// Number of state-event functions located by integrators that find roots (0: none).
  virtual int eventCount() const { return 0; }
  /// (t, q, v) => g_j for every event function; an event is a sign change of g_j.
  virtual void eventFunctions(double /*t*/, const Eigen::VectorXd& /*q*/, const Eigen::VectorXd& /*v*/,
                              std::span<double> /*g*/) {}
};

/// (source, t, q, v) => its linearisation about (t, q, v) for the scope's lifetime (ended also
/// when a finite difference throws)
class LinearisedScope {
 public:
  LinearisedScope(AccelerationSource& source, double t, const Eigen::VectorXd& q,
                  const Eigen::VectorXd& v)
      : source_(source) {
    source_.beginLinearisation(t, q, v);
  }
  ~LinearisedScope() { source_.endLinearisation(); }
  LinearisedScope(const LinearisedScope&) = delete;
  LinearisedScope& operator=(const LinearisedScope&) = delete;

 private:
  AccelerationSource& source_;
};

/// Work counters of an integrator since construction or resetStats().
struct IntegratorStats {
  long steps = 0;       ///< accepted steps (internal steps for adaptive methods)
  long f_evals = 0;     ///< acceleration (ABA / forward dynamics) evaluations
  long jac_evals = 0;   ///< Jacobian (iteration matrix) evaluations
  long newton_its = 0;  ///< Newton (nonlinear solver) iterations
  long err_fails = 0;   ///< error-test failures (adaptive) or rejected Newton solves
  long factorisations = 0;  ///< LU factorisations of the iteration matrix (implicit methods)
  long conv_fails = 0;      ///< failed Newton solves of an adaptive method (CVODE, ARKODE)
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  /// (t, q, v) => (t + h, q, v) after one step of size h. No allocation after the first step.
  /// An adaptive method takes as many internal steps as its tolerances need. With findRoots(true)
  /// and a source that has event functions, a root finder stops earlier: t is then the located
  /// time and lastEvent() the function's index.
  virtual void step(AccelerationSource& system, double& t, Eigen::VectorXd& q, Eigen::VectorXd& v, double h) = 0;
  virtual std::string_view name() const = 0;
  /// Forget the history (multistep values, algorithmic accelerations, adaptive step): the next
  /// step starts afresh. Methods also restart by themselves when a step does not begin where
  /// the previous one ended (an external event changed the state, or a step is re-taken).
  virtual void reset() {}
  /// Whether the method carries a history from step to step (multistep values, algorithmic
  /// accelerations, an adaptive solver's order and step) that reset() forgets; a checkpoint is a
  /// restart point of that history (docs/scenes.md, checkpoints).
  virtual bool carriesHistory() const { return false; }
  /// Whether step() can stop at state events (root finding; the SUNDIALS methods).
  virtual bool canFindRoots() const { return false; }
  void findRoots(bool on) { roots_ = on && canFindRoots(); }
  /// Index of the event function whose root ended the last step, or -1.
  int lastEvent() const { return lastEvent_; }

  const IntegratorStats& stats() const { return stats_; }
  void resetStats() { stats_ = {}; }

 protected:
  /// (t, q, v) => a through the source, counted in stats().f_evals.
  void evaluate(AccelerationSource& s, double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                Eigen::VectorXd& a) {
    ++stats_.f_evals;
    s.acceleration(t, q, v, a);
  }
  IntegratorStats stats_;
  bool roots_ = false;
  int lastEvent_ = -1;
};

}  // namespace yardsim::dynamics
