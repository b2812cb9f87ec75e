#pragma once
// The generalized-alpha method (Chung & Hulbert 1993) in the form of Arnold & Bruls (2007) for
// constrained systems on the configuration manifold, with HHT-alpha as a parameter choice:
//   q_{n+1} = q_n (+) h (v_n + h b_n / 2 + h (1/2 - beta) a_n + h beta a_{n+1})
//   v_{n+1} = v_n + h ((1 - gamma) a_n + gamma a_{n+1})
//   (1 - alpha_m) a_{n+1} + alpha_m a_n = (1 - alpha_f) ddq_{n+1} + alpha_f ddq_n
//   ddq_{n+1} = f(t_{n+1}, q_{n+1}, v_{n+1}) + M^-1 J^T lambda_{n+1},   g(q_{n+1}) = 0   (index 3)
// where f is the tree's forward dynamics without the loops and b_n the second derivative of the
// chart coordinate at q_n beyond the acceleration (w x v for a free joint's translation, whose
// velocity is in the body frame; zero for the other joints), which keeps second order on the
// configuration manifold. The unknowns (ddq_{n+1}, lambda) are
// solved by Newton with an iteration matrix [I - beta' h^2 F_q - gamma' h F_v, -M^-1 J^T; J, 0]
// (F = f + M^-1 J^T lambda, its derivatives by finite differences; dense, or sparse with one
// evaluation per column colour when the system reports the structure of its Jacobian, as with
// lumped-mass lines: sparse_newton_matrix.hpp) that is factorised once and reused over steps
// until Newton slows down; a failed solve is retried with a fresh matrix at the predictor, then
// with one at the last iterate (a rope going taut inside the step), then as two half steps, down
// (the blocks a system gives in closed form, a lumped line's nodes, are re-evaluated at every
// iterate, and the matrix refactorised when a segment went slack or taut or a node touched the
// bed, at every iterate when its bordered band factorisation makes that cheap: a semi-smooth
// Newton on those rows; the other entries stay as formed. With such blocks a failed solve is
// first continued from its last iterate with the current matrix, the fresh matrix at the
// predictor is skipped, and only a solve slower still marks the matrix stale, or a slow rescue
// with a matrix that has served kAgedSteps steps: docs/lines.md)
// to h/16; a sixteenth that still has no solution (a force that jumps: a damped rope going taut)
// is crossed by one RK4 sub-step, and the method restarts after it. The algorithmic acceleration
// starts at a_0 = ddq_0 + (alpha_m - alpha_f) h dddq_0 ~ ddq(t_0 + (alpha_m - alpha_f) h), which
// keeps second order for alpha_m != alpha_f (Arnold & Bruls 2007); dddq_0 comes from one extra
// evaluation (a forward difference along (v, ddq)).

#include <Eigen/LU>
#include <memory>

#include "dynamics/integrators/integrator.hpp"
#include "dynamics/integrators/rk4.hpp"
#include "dynamics/integrators/sparse_newton_matrix.hpp"
#include "dynamics/model.hpp"

namespace yardsim::dynamics {

struct GeneralizedAlphaParameters {
  double alphaM = 0.0, alphaF = 0.0, beta = 0.25, gamma = 0.5;
};

/// (rho_inf in [0, 1]) => Chung-Hulbert parameters: alpha_m = (2 rho - 1)/(rho + 1),
/// alpha_f = rho/(rho + 1), gamma = 1/2 + alpha_f - alpha_m, beta = (gamma + 1/2)^2 / 4.
GeneralizedAlphaParameters chungHulbert(double rhoInf);

class GeneralizedAlpha final : public Integrator {
 public:
  GeneralizedAlpha(const Model& model, const GeneralizedAlphaParameters& p, std::string_view name,
                   double newtonTol = 1e-8, int maxNewton = 8);
  void step(AccelerationSource& system, double& t, Eigen::VectorXd& q, Eigen::VectorXd& v,
            double h) override;
  std::string_view name() const override { return name_; }
  void reset() override {
    started_ = false;
    resolving_ = false;
  }
  bool carriesHistory() const override { return true; }
  const GeneralizedAlphaParameters& parameters() const { return p_; }
  /// Lagrange multipliers of the last step (size rows of the loops).
  const Eigen::VectorXd& multipliers() const { return lambda_; }
  /// (on) => a fresh iteration matrix at the start of every step instead of reusing it until
  /// Newton slows: the reference of the reuse's tests (off by default)
  void refreshEveryStep(bool on) { refreshEveryStep_ = on; }

 private:
  void resize(int nc);
  void start(AccelerationSource& system, double t, const Eigen::VectorXd& q,
             const Eigen::VectorXd& v, double h);
  // (ddq) => a_{n+1}, qNew_, vNew_ from the state at the start of the step
  void update(const Eigen::VectorXd& q, const Eigen::VectorXd& v, double h);
  // (v_n) => bias_, the chart's own second derivative at q_n
  void chartBias(const Eigen::VectorXd& v);
  // (state at the end of the step) => f_q, f_v by finite differences; factorised for h
  void jacobian(AccelerationSource& system, double t, const Eigen::VectorXd& q, double h);
  void factorise(double h);
  // (system with closed-form blocks, the iterate (qNew_, vNew_) at t) => the blocks written into
  // the sparse matrix; true when a force law switched since they were last written
  bool refreshBlocks(AccelerationSource& system, double t);
  // the sparse matrix has blocks in closed form (lumped lines), and they are cheap to refactorise
  bool lineBlocks() const { return sparseActive_ && sparse_->hasBlocks(); }
  bool cheapBlocks() const { return lineBlocks() && sparse_->banded(); }
  // (x) => A^-1 x by the dense or the sparse LU, whichever the last jacobian() formed
  void solveA(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;
  // (step of h) => Newton with the current matrix, then with a fresh one (line blocks: continued
  // from the last iterate instead); false if both fail
  bool attempt(AccelerationSource& system, double t, const Eigen::VectorXd& q,
               const Eigen::VectorXd& v, double h);
  // (step of h) => state advanced, in halves (down to h/16) where Newton fails
  void advance(AccelerationSource& system, double& t, Eigen::VectorXd& q, Eigen::VectorXd& v,
               double h, int depth);
  // one Newton solve from the predictor (or from the current ddq_); false when it does not converge
  bool solve(AccelerationSource& system, double t, const Eigen::VectorXd& q,
             const Eigen::VectorXd& v, double h, bool fromPredictor);

  const Model& model_;
  GeneralizedAlphaParameters p_;
  std::string_view name_;
  // a step whose start and end differ in the source's regime (a contact closed or opened) is
  // taken again as kSwitchSteps equal sub-steps, and so are the steps after it while the regime
  // changes inside them (docs/integrators.md "Switching forces"); the sub-steps' depth kSubStep
  // marks them: not checked again, not halved (RK4 where Newton fails)
  static constexpr int kSwitchSteps = 256, kSubStep = 1000;
  std::uint64_t regime_ = 0;  // the source's regime at the start of the next (sub-)step
  bool resolving_ = false;    // the last step's regime changed in its sub-steps
  // (step of h) => kSwitchSteps sub-steps; resolving_ set when the regime changed in them
  void subSteps(AccelerationSource& system, double& t, Eigen::VectorXd& q, Eigen::VectorXd& v,
                double h);
  double newtonTol_;
  int maxNewton_;
  Rk4 explicitStep_;  // crosses a force jump where Newton has no solution
  bool started_ = false, fresh_ = false, stale_ = true, refreshEveryStep_ = false;
  // steps taken with the current iteration matrix; with line blocks a slow rescued solve
  // refreshes a matrix older than kAgedSteps (attempt())
  static constexpr long kAgedSteps = 20;
  long matrixSteps_ = 0;
  int nc_ = -1;
  double hFactor_ = 0.0, tLast_ = 0.0;
  Eigen::VectorXd bias_, aAlg_, ddq_, ddqOld_, aNew_, delta_, qNew_, vNew_, f_, fp_, r_, dx_,
      qLast_, vLast_;
  Eigen::VectorXd qp_, vp_, deltaP_;
  Eigen::MatrixXd Fq_, Fv_, A_;  // the dense path only: sized at its first jacobian()
  Eigen::PartialPivLU<Eigen::MatrixXd> luA_;
  // the sparse path: made at the first jacobian() of a system with a pattern
  std::unique_ptr<SparseNewtonMatrix> sparse_;
  const JacobianPattern* sparseFor_ = nullptr;  // the pattern sparse_ was made for
  bool sparseActive_ = false;
  // loops
  Eigen::VectorXd g_, lambda_, lambdaStart_, dlambda_, rc_, pivoted_;  // pivoted_: S's solve
  Eigen::MatrixXd J_, MinvJt_, Jf_, MinvJtf_, AinvMinvJt_, S_;
  Eigen::FullPivLU<Eigen::MatrixXd> luS_;
};

}  // namespace yardsim::dynamics
