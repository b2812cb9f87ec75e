#pragma once
// What the SUNDIALS integrators (cvode.hpp, arkode.hpp) share: the multibody state as a flat
// N_Vector through ChartState, the right-hand side and root functions handed to the solver, and
// the step logic. A step continues the solver's own history (order, step size) while it starts
// where the previous one ended; otherwise (an external event changed the state, a state event is
// being located by re-advancing, the post-step projection moved the state, or the chart has
// rotated more than 1 rad) the solver is re-initialised there. Each step stops exactly at t + h
// (a stop time), so set-points changing between steps are never integrated across.
// Tolerances: atol (m, rad, m/s, rad/s) and rtol act on positions and velocities; see atol_.

#include <exception>
#include <memory>
#include <string>

#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>

#include "dynamics/integrators/chart_newton_system.hpp"
#include "dynamics/integrators/chart_state.hpp"
#include "dynamics/integrators/factory.hpp"
#include "dynamics/integrators/integrator.hpp"
#include "dynamics/integrators/sundials_vector_pool.hpp"

namespace yardsim::dynamics {

class AdaptiveIntegrator : public Integrator {
 public:
  ~AdaptiveIntegrator() override;
  AdaptiveIntegrator(const AdaptiveIntegrator&) = delete;
  AdaptiveIntegrator& operator=(const AdaptiveIntegrator&) = delete;

  void step(AccelerationSource& system, double& t, Eigen::VectorXd& q, Eigen::VectorXd& v, double h) final;
  bool canFindRoots() const final { return true; }
  void reset() final { initialised_ = false; }
  bool carriesHistory() const override { return true; }

  /// (on) => keep SUNDIALS' dense Newton (difference-quotient Jacobian, dense LU) even for a
  /// system with a Jacobian pattern (lumped lines), which otherwise gets the chart Newton system
  /// (chart_newton_system.hpp); before the first step (comparisons in tests and benches)
  void useDenseNewton(bool on) { denseNewton_ = on; }
  /// (steps) => with the chart Newton system, a fresh Jacobian at least every that many steps
  /// (CVODE; default 1000, docs/integrators.md); 1: at every step, the reuse's tests' reference.
  /// Before the first step
  void setLinesJacobianAge(long steps) { linesJacobianAge_ = steps; }

  /// The pool of the solver's empty vectors (sundials_vector_pool.hpp): how many SUNDIALS' dense
  /// difference-quotient Jacobians took from it (one each), for tests
  const SundialsVectorPool& vectorPool() const { return *pool_; }

  /// Which part of dy/dt a right-hand side returns (IMEX splits kinematics from dynamics).
  enum class Part { All, Kinematic, Dynamic };
  /// (t, y) => ydot (the part asked for); 0, or -1 after the source threw (kept for rethrow).
  int rightHandSide(double t, N_Vector y, N_Vector ydot, Part part);
  /// (t, y) => g_j; 0, or -1 after the source threw.
  int rootFunctions(double t, N_Vector y, double* g);
  /// The last error message of the solver (its error handler).
  void solverError(const char* module, const char* function, const char* message);
  /// (t, y, fy = f(t, y), whether the solver lets the Jacobian be reused, gamma) => the chart
  /// Newton system formed (jok false: F_q, F_v by colours, *jcur true) or its closed-form blocks
  /// refreshed, and factorised for gamma; 0, or -1 after the source threw (the solvers' linear
  /// system function, with makeChartSolver()'s solver)
  int linearSystem(double t, N_Vector y, N_Vector fy, bool jok, int* jcur, double gamma);
  /// (t, y, fy = the part at (t, y), the dense matrix J, a work vector, the part) => J = d part/dy
  /// by forward differences, the source's forces with an analytic linearisation taking it about
  /// (t, y) (AccelerationSource::beginLinearisation); 0, or -1 after the source threw. The dense
  /// path's Jacobian function for a source that linearises() (denseJacobianWanted()); any other
  /// keeps SUNDIALS' own difference quotients.
  int denseJacobian(double t, N_Vector y, N_Vector fy, SUNMatrix J, N_Vector work, Part part);

 protected:
  AdaptiveIntegrator(const Model& model, const IntegratorSpec& spec);
  /// (y_ at t) => solver created (first call) or re-initialised, tolerances and roots set.
  virtual void init(double t, int roots) = 0;
  /// (tout) => y_ at tret; the solver's flag (< 0: failure, root: rootReturn()).
  virtual int advance(double tout, double& tret) = 0;
  virtual bool rootReturn(int flag) const = 0;
  /// (after a root return) => which function crossed (found[j] != 0).
  virtual void rootInfo(int* found) = 0;
  /// Cumulative counters of the solver since it was (re)initialised (f_evals is counted here).
  virtual void counters(IntegratorStats& s) = 0;
  /// A dense matrix and linear solver for y_, made on first use.
  void makeLinearSolver();
  /// (whether theta' = G v is in the implicit part) => for a source with a Jacobian pattern
  /// (lumped lines) and without useDenseNewton(true), the chart Newton system's stand-in matrix and
  /// solver in A_, LS_ (sundials_chart_solver.hpp; made on first use) and true: the caller then
  /// sets linearSystem() as the solver's linear system function; else false (the dense path)
  bool makeChartSolver(bool kinematicImplicit);
  /// Whether the dense path should set denseJacobian() as the solver's Jacobian function: the
  /// source has forces with an analytic linearisation (a quasi-static catenary line).
  bool denseJacobianWanted() const { return source_ != nullptr && source_->linearises(); }

  const Model& model_;
  IntegratorSpec spec_;
  SUNContext ctx_ = nullptr;
  std::unique_ptr<SundialsVectorPool> pool_;  // y_'s, atol_'s and their clones' empty clones
  N_Vector y_ = nullptr;
  /// Absolute tolerance per component: atol, plus rtol |q*| for the chart coordinate of a joint
  /// whose q is a plain coordinate, so that rtol acts on positions, not on displacements from q*.
  N_Vector atol_ = nullptr;
  SUNMatrix A_ = nullptr;
  SUNLinearSolver LS_ = nullptr;
  void* mem_ = nullptr;
  std::string error_;
  long linesJacobianAge_ = 1000;  // steps between coloured Jacobians with lumped lines (CVODE)

 private:
  ChartState chart_;
  AccelerationSource* source_ = nullptr;
  bool initialised_ = false;
  int nroots_ = 0;  // event functions the solver was initialised with
  std::exception_ptr thrown_;
  double tLast_ = 0.0;
  Eigen::VectorXd q_, v_, a_, qLast_, vLast_, qOut_, vOut_;
  std::vector<int> found_;
  std::vector<double> g_;
  // the sparse path: the chart Newton system, made at the first linearSystem() for the pattern
  std::unique_ptr<ChartNewtonSystem> newton_;
  const JacobianPattern* newtonFor_ = nullptr;
  bool kinematicImplicit_ = true;
  bool denseNewton_ = false;
};

}  // namespace yardsim::dynamics
