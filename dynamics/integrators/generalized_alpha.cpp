#include "dynamics/integrators/generalized_alpha.hpp"

#include <cmath>
#include <limits>

#include "dynamics/configuration.hpp"

namespace yardsim::dynamics {

namespace {

// (full-pivoting LU of a square S, b; a work vector c sized like b) => x = S^-1 b by the steps
// and operations of FullPivLU::solve (Eigen 3.4's _solve_impl: the same doubles), without the
// temporary it allocates at every call: c = P b, L and then U (its rank's corner) solved in
// place, x = Q c with the unknowns beyond the rank zero
void solveFullPivot(const Eigen::FullPivLU<Eigen::MatrixXd>& lu, const Eigen::VectorXd& b,
                    Eigen::VectorXd& c, Eigen::VectorXd& x) {
  const Eigen::Index rank = lu.rank();
  if (rank == 0) {
    x.setZero();
    return;
  }
  c.noalias() = lu.permutationP() * b;
  lu.matrixLU().triangularView<Eigen::UnitLower>().solveInPlace(c);
  lu.matrixLU().topLeftCorner(rank, rank).triangularView<Eigen::Upper>().solveInPlace(c.head(rank));
  const auto& q = lu.permutationQ().indices();
  for (Eigen::Index i = 0; i < lu.cols(); ++i) x[q[i]] = i < rank ? c[i] : 0.0;
}

}  // namespace

GeneralizedAlphaParameters chungHulbert(double rho) {
  GeneralizedAlphaParameters p;
  p.alphaM = (2.0 * rho - 1.0) / (rho + 1.0);
  p.alphaF = rho / (rho + 1.0);
  p.gamma = 0.5 + p.alphaF - p.alphaM;
  p.beta = 0.25 * (p.gamma + 0.5) * (p.gamma + 0.5);
  return p;
}

GeneralizedAlpha::GeneralizedAlpha(const Model& model, const GeneralizedAlphaParameters& p,
                                   std::string_view name, double newtonTol, int maxNewton)
    : model_(model),
      p_(p),
      name_(name),
      newtonTol_(newtonTol),
      maxNewton_(maxNewton),
      explicitStep_(model) {
  const int n = model.nv;
  for (Eigen::VectorXd* x : {&bias_, &aAlg_, &ddq_, &ddqOld_, &aNew_, &delta_, &vNew_, &f_, &fp_,
                             &r_, &dx_, &vLast_, &vp_, &deltaP_})
    x->setZero(n);
  for (Eigen::VectorXd* x : {&qNew_, &qLast_, &qp_}) x->setZero(model.nq);
  resize(0);
}

void GeneralizedAlpha::resize(int nc) {
  if (nc == nc_) return;
  nc_ = nc;
  const int n = model_.nv;
  for (Eigen::VectorXd* x : {&g_, &lambda_, &lambdaStart_, &dlambda_, &rc_, &pivoted_})
    x->setZero(nc);
  for (Eigen::MatrixXd* x : {&J_, &Jf_}) x->setZero(nc, n);
  for (Eigen::MatrixXd* x : {&MinvJt_, &MinvJtf_, &AinvMinvJt_}) x->setZero(n, nc);
  S_.setZero(nc, nc);
  luS_ = Eigen::FullPivLU<Eigen::MatrixXd>(nc, nc);
  luS_.setThreshold(1e-10);
}

void GeneralizedAlpha::start(AccelerationSource& system, double t, const Eigen::VectorXd& q,
                             const Eigen::VectorXd& v, double h) {
  // (t, q, v) => ddq_0 (with the loops' forces); a_0 = ddq_0 + (alpha_m - alpha_f) h dddq_0, the
  // perturbed starting value of Arnold & Bruls, dddq_0 by a forward difference along (v, ddq_0)
  evaluate(system, t, q, v, ddqOld_);
  aAlg_ = ddqOld_;
  const double shift = (p_.alphaM - p_.alphaF) * h;
  if (shift != 0.0) {
    const double eps =
        std::sqrt(std::numeric_limits<double>::epsilon()) /
        std::max(1.0, std::max(v.lpNorm<Eigen::Infinity>(), ddqOld_.lpNorm<Eigen::Infinity>()));
    integrate(model_, q, v, eps, qp_);
    vp_ = v + eps * ddqOld_;
    evaluate(system, t + eps, qp_, vp_, aNew_);
    // (correction) => dropped when larger than ddq_0 itself: the difference then straddles a force
    // that jumps (a damped rope going taut), not a smooth dddq
    aNew_ = (shift / eps) * (aNew_ - ddqOld_);
    if (aNew_.lpNorm<Eigen::Infinity>() <= std::max(1.0, ddqOld_.lpNorm<Eigen::Infinity>()))
      aAlg_ += aNew_;
  }
  lambda_.setZero();
  started_ = true;
}

void GeneralizedAlpha::chartBias(const Eigen::VectorXd& v) {
  // (v) => b = d/dtheta chartRate(theta, v) v at theta = 0, by a central difference: the second
  // derivative of the chart coordinate beyond a (w x v for the translation of a free joint)
  if (model_.euclidean) return;
  const double eps = 1e-4 / std::max(1.0, v.lpNorm<Eigen::Infinity>());
  deltaP_ = eps * v;
  chartRate(model_, deltaP_, v, bias_);
  deltaP_ = -eps * v;
  chartRate(model_, deltaP_, v, fp_);
  bias_ = (bias_ - fp_) / (2.0 * eps);
}

void GeneralizedAlpha::update(const Eigen::VectorXd& q, const Eigen::VectorXd& v, double h) {
  // (ddq_{n+1}, a_n, ddq_n) => a_{n+1}; (q_n, v_n) => q_{n+1}, v_{n+1}
  aNew_ = ((1.0 - p_.alphaF) * ddq_ + p_.alphaF * ddqOld_ - p_.alphaM * aAlg_) / (1.0 - p_.alphaM);
  delta_ =
      h * v + (0.5 * h * h) * bias_ + (h * h * (0.5 - p_.beta)) * aAlg_ + (h * h * p_.beta) * aNew_;
  integrate(model_, q, delta_, 1.0, qNew_);
  vNew_ = v + (h * (1.0 - p_.gamma)) * aAlg_ + (h * p_.gamma) * aNew_;
}

void GeneralizedAlpha::jacobian(AccelerationSource& system, double t, const Eigen::VectorXd& q,
                                double h) {
  // (q_{n+1}, v_{n+1} of the predictor) => f, then f_q (through the chart at q_n) and f_v column by
  // column (with loops, the constraint force M^-1 J^T lambda is part of f here: quadratic
  // convergence)
  ++stats_.jac_evals;
  ++stats_.f_evals;
  system.unconstrainedAcceleration(t + h, qNew_, vNew_, f_);
  if (nc_ > 0) {
    system.constraintTerms(qNew_, g_, Jf_, MinvJtf_);
    f_.noalias() += MinvJtf_ * lambda_;
  }
  const double eps = std::sqrt(std::numeric_limits<double>::epsilon());
  // (the predictor's state) => the forces with an analytic linearisation take it for the columns
  const LinearisedScope linearised(system, t + h, qNew_, vNew_);
  const JacobianPattern* pattern = system.jacobianPattern();
  sparseActive_ = pattern != nullptr;
  if (sparseActive_) {
    // (a structured system) => F_q, F_v by column colours (sparse_newton_matrix.hpp)
    if (sparseFor_ != pattern)
      sparse_ = std::make_unique<SparseNewtonMatrix>(model_, *pattern, system.jacobianBlocks());
    sparseFor_ = pattern;
    stats_.f_evals += sparse_->form(
        [&](const Eigen::VectorXd& qs, const Eigen::VectorXd& vs, bool qMoved,
            Eigen::VectorXd& out) {
          system.unconstrainedAcceleration(t + h, qs, vs, out);
          if (nc_ > 0 && qMoved) system.constraintTerms(qs, g_, J_, MinvJt_);
          if (nc_ > 0) out.noalias() += (qMoved ? MinvJt_ : MinvJtf_) * lambda_;
        },
        q, delta_, qNew_, vNew_, f_);
    refreshBlocks(system, t + h);
  } else if (Fq_.rows() != model_.nv) {
    // (the dense path's first matrix) => its storage, made here and not at construction: a
    // system with a pattern (lumped lines, thousands of dofs) never needs the n x n matrices
    const int n = model_.nv;
    Fq_.setZero(n, n);
    Fv_.setZero(n, n);
    A_.setZero(n, n);
    luA_ = Eigen::PartialPivLU<Eigen::MatrixXd>(n);
  }
  for (int i = 0; i < model_.nv && !sparseActive_; ++i) {
    const double dqi = eps * std::max(1.0, std::abs(delta_[i]));
    deltaP_ = delta_;
    deltaP_[i] += dqi;
    integrate(model_, q, deltaP_, 1.0, qp_);
    ++stats_.f_evals;
    system.unconstrainedAcceleration(t + h, qp_, vNew_, fp_);
    if (nc_ > 0) {
      system.constraintTerms(qp_, g_, J_, MinvJt_);
      fp_.noalias() += MinvJt_ * lambda_;
    }
    Fq_.col(i) = (fp_ - f_) / dqi;
    const double dvi = eps * std::max(1.0, std::abs(vNew_[i]));
    vp_ = vNew_;
    vp_[i] += dvi;
    ++stats_.f_evals;
    system.unconstrainedAcceleration(t + h, qNew_, vp_, fp_);
    if (nc_ > 0) fp_.noalias() += MinvJtf_ * lambda_;
    Fv_.col(i) = (fp_ - f_) / dvi;
  }
  fresh_ = true;
  stale_ = false;
  matrixSteps_ = 0;
  factorise(h);
}

void GeneralizedAlpha::factorise(double h) {
  // (f_q, f_v, h) => LU of A = I - beta' h^2 f_q - gamma' h f_v; Schur complement J A^-1 M^-1 J^T
  const double s = (1.0 - p_.alphaF) / (1.0 - p_.alphaM);
  ++stats_.factorisations;
  if (sparseActive_) {
    sparse_->factorise(p_.beta * s * h * h, p_.gamma * s * h);
  } else {
    A_ = -(p_.beta * s * h * h) * Fq_ - (p_.gamma * s * h) * Fv_;
    A_.diagonal().array() += 1.0;
    luA_.compute(A_);
  }
  if (nc_ > 0) {
    if (sparseActive_)
      sparse_->solve(MinvJtf_, AinvMinvJt_);
    else
      AinvMinvJt_ = luA_.solve(MinvJtf_);
    S_.noalias() = Jf_ * AinvMinvJt_;
    luS_.compute(S_);
  }
  hFactor_ = h;
}

bool GeneralizedAlpha::refreshBlocks(AccelerationSource& system, double t) {
  if (!sparseActive_ || !sparse_->hasBlocks()) return false;
  const std::uint64_t signature =
      system.blockJacobian(t, qNew_, vNew_, sparse_->blockDq(), sparse_->blockDv());
  return sparse_->applyBlocks(signature);
}

void GeneralizedAlpha::solveA(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  if (sparseActive_)
    sparse_->solve(b, x);
  else
    x = luA_.solve(b);
}

bool GeneralizedAlpha::solve(AccelerationSource& system, double t, const Eigen::VectorXd& q,
                             const Eigen::VectorXd& v, double h, bool fromPredictor) {
  const double s = (1.0 - p_.alphaF) / (1.0 - p_.alphaM);
  const double scale = std::max(p_.beta * s * h * h, p_.gamma * s * h);
  if (fromPredictor) ddq_ = ddqOld_;
  double errPrev = std::numeric_limits<double>::infinity();
  for (int it = 0; it < maxNewton_; ++it) {
    // (ddq, lambda) => residual r = ddq - f - M^-1 J^T lambda, r_c = g / (beta' h^2)
    update(q, v, h);
    ++stats_.f_evals;
    ++stats_.newton_its;
    system.unconstrainedAcceleration(t + h, qNew_, vNew_, f_);
    r_ = ddq_ - f_;
    if (nc_ > 0) {
      system.constraintTerms(qNew_, g_, J_, MinvJt_);
      r_.noalias() -= MinvJt_ * lambda_;
      rc_ = g_ / (p_.beta * s * h * h);
    }
    // (a line's segment went slack or taut, a node touched the bed) => its blocks here, the
    // matrix refactorised with them; at every iterate after the first when the band solver
    // makes that cheap (a semi-smooth Newton on the line rows)
    if (refreshBlocks(system, t + h) || (it > 0 && cheapBlocks())) factorise(h);
    // (r, r_c) => corrections: S dlambda = -r_c + J A^-1 r, dx = A^-1 (-r + M^-1 J^T dlambda)
    solveA(r_, dx_);
    if (nc_ > 0) {
      rc_.noalias() -= Jf_ * dx_;
      solveFullPivot(luS_, rc_, pivoted_, dlambda_);
      dlambda_ = -dlambda_;
      dx_.noalias() -= AinvMinvJt_ * dlambda_;
      lambda_ += dlambda_;
    }
    ddq_ -= dx_;
    if (!ddq_.allFinite()) return false;
    // (correction) => converged when it moves q_{n+1} and v_{n+1} less than the tolerance, relative
    // to the terms of the update when they exceed 1 (their round-off bounds what can be reached)
    const double err = scale * dx_.lpNorm<Eigen::Infinity>();
    const double motion = std::max(
        1.0, h * v.lpNorm<Eigen::Infinity>() +
                 h * h * (aAlg_.lpNorm<Eigen::Infinity>() + aNew_.lpNorm<Eigen::Infinity>()));
    if (err <= newtonTol_ * motion) {
      // (slow: a new iteration matrix for the next step; with line blocks, which are fresh at
      // every iterate, only when slower still)
      if (it + 1 >= maxNewton_ - (lineBlocks() ? 1 : 2)) stale_ = true;
      update(q, v, h);
      return true;
    }
    if (err > 0.9 * errPrev) return false;
    errPrev = err;
  }
  return false;
}

void GeneralizedAlpha::step(AccelerationSource& system, double& t, Eigen::VectorXd& q,
                            Eigen::VectorXd& v, double h) {
  resize(system.constraintRows());
  // (t, q, v) => restart unless this step continues the previous one
  const double tol = 1e-9 * std::max(1.0, std::abs(t));
  if (!started_ || std::abs(t - tLast_) > tol || q != qLast_ || v != vLast_) {
    start(system, t, q, v, h);
    if (system.switches()) regime_ = system.regime(t, q, v);
    resolving_ = false;
  }
  advance(system, t, q, v, h, 0);
  tLast_ = t;
  qLast_ = q;
  vLast_ = v;
}

bool GeneralizedAlpha::attempt(AccelerationSource& system, double t, const Eigen::VectorXd& q,
                               const Eigen::VectorXd& v, double h) {
  fresh_ = false;
  chartBias(v);
  // (iteration matrix) => refreshed when stale, refactorised when h changed
  if (stale_ || refreshEveryStep_) {
    ddq_ = ddqOld_;
    update(q, v, h);
    jacobian(system, t, q, h);
  } else if (h != hFactor_) {
    factorise(h);
  }
  lambdaStart_ = lambda_;
  const long iterations = stats_.newton_its;
  if (solve(system, t, q, v, h, true)) return true;
  ++stats_.err_fails;
  // (line blocks: the first correction from the predictor crossed a segment's slack/taut corner
  // and the next one came back; the blocks are current, a fresh matrix from the predictor would
  // repeat it) => Newton continued from the last iterate with the current matrix. When the two
  // solves together were as slow as a stale matrix's and the matrix has served kAgedSteps steps,
  // its rigid columns aged past a fast change of the rigid forces (a stop struck; a corner
  // crossed just after a fresh matrix is the lines') => a fresh matrix for the next step
  if (lineBlocks() && ddq_.allFinite()) {
    if (solve(system, t, q, v, h, false)) {
      if (stats_.newton_its - iterations >= maxNewton_ - 1 && matrixSteps_ >= kAgedSteps)
        stale_ = true;
      return true;
    }
    ++stats_.err_fails;
  }
  // (failed with an old matrix, no line blocks) => once more with a fresh one at the predictor
  if (!fresh_ && !lineBlocks()) {
    lambda_ = lambdaStart_;
    ddq_ = ddqOld_;
    update(q, v, h);
    jacobian(system, t, q, h);
    if (solve(system, t, q, v, h, true)) return true;
    ++stats_.err_fails;
  }
  // (failed across a kink, e.g. a rope going taut: the predictor's matrix lacks its stiffness) =>
  // a matrix at the last iterate, and Newton from there. (line blocks) => false: the step is
  // halved at once; the blocks are current at every iterate, and in issue 17's buoy bench a fresh
  // matrix here let 2 of 25 steps converge, at about 50 stage evaluations each. Its rigid part is
  // refreshed when Newton is slow (stale_) and after an RK4 sub-step at h/16
  if (!ddq_.allFinite() || lineBlocks()) return false;
  update(q, v, h);
  jacobian(system, t, q, h);
  if (solve(system, t, q, v, h, false)) return true;
  ++stats_.err_fails;
  lambda_ = lambdaStart_;
  return false;
}

void GeneralizedAlpha::subSteps(AccelerationSource& system, double& t, Eigen::VectorXd& q,
                                Eigen::VectorXd& v, double h) {
  // (step of h) => kSwitchSteps equal sub-steps, the regime read after each; resolving_ while
  // the regime changed at any of them (the next step is sub-stepped at once), false once a whole
  // step kept it
  bool changed = false;
  for (int k = 0; k < kSwitchSteps; ++k) {
    advance(system, t, q, v, h / kSwitchSteps, kSubStep);
    const std::uint64_t r = system.regime(t, q, v);
    changed = changed || r != regime_;
    regime_ = r;
  }
  resolving_ = changed;
}

void GeneralizedAlpha::advance(AccelerationSource& system, double& t, Eigen::VectorXd& q,
                               Eigen::VectorXd& v, double h, int depth) {
  if (resolving_ && depth < kSubStep && system.switches()) {
    subSteps(system, t, q, v, h);
    return;
  }
  if (!attempt(system, t, q, v, h)) {
    // (Newton failed, e.g. a rope going taut inside the step) => two half steps, down to h / 16
    // (sparse path: a Jacobian costs O(colours) stages) => the halves keep the last matrix,
    // refactorised for h/2, and attempt() forms a fresh one only where it fails again
    if (depth < 4) {
      stale_ = !sparseActive_;
      advance(system, t, q, v, 0.5 * h, depth + 1);
      stale_ = stale_ || !sparseActive_;
      advance(system, t, q, v, 0.5 * h, depth + 1);
      return;
    }
    // (no solution at h/16: a force that jumps, like a damped rope going taut) => one RK4
    // sub-step across it, and a fresh start after it
    explicitStep_.step(system, t, q, v, h);
    stats_.f_evals += 4;
    ++stats_.steps;
    start(system, t, q, v, h);
    if (system.switches()) regime_ = system.regime(t, q, v);
    stale_ = true;
    return;
  }
  // (converged, but a switching force changed branch inside the step: a contact closed or opened
  // that the step does not resolve) => taken again in sub-steps
  if (system.switches() && depth < kSubStep) {
    const std::uint64_t end = system.regime(t + h, qNew_, vNew_);
    if (end != regime_) {
      lambda_ = lambdaStart_;
      subSteps(system, t, q, v, h);
      return;
    }
    regime_ = end;
  }
  // (converged) => new state and history
  q = qNew_;
  v = vNew_;
  ddqOld_ = ddq_;
  aAlg_ = aNew_;
  t += h;
  ++stats_.steps;
  ++matrixSteps_;
  system.afterStep(t, q, v);
}

}  // namespace yardsim::dynamics
