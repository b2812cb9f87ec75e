#include "dynamics/integrators/adaptive_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include "dynamics/integrators/sundials_chart_solver.hpp"

namespace yardsim::dynamics {

AdaptiveIntegrator::AdaptiveIntegrator(const Model& model, const IntegratorSpec& spec)
    : model_(model),
      spec_(spec),
      chart_(model),
      q_(model.nq),
      v_(model.nv),
      a_(model.nv),
      qLast_(model.nq),
      vLast_(model.nv),
      qOut_(model.nq),
      vOut_(model.nv) {
  if (SUNContext_Create(nullptr, &ctx_) != 0) throw std::runtime_error("SUNDIALS: cannot create a context");
  // (the state's length) => y_, atol_ and, through their clones, every vector of the solver, with
  // the pool's empty clones for SUNDIALS' difference-quotient Jacobian (sundials_vector_pool.hpp)
  pool_ = std::make_unique<SundialsVectorPool>(ctx_, chart_.size());
  y_ = pool_->makeVector();
  atol_ = pool_->makeVector();
  N_VConst(spec.atol, atol_);
}

AdaptiveIntegrator::~AdaptiveIntegrator() {
  if (LS_ != nullptr) SUNLinSolFree(LS_);
  if (A_ != nullptr) SUNMatDestroy(A_);
  if (atol_ != nullptr) N_VDestroy(atol_);
  if (y_ != nullptr) N_VDestroy(y_);
  pool_.reset();  // (after every vector using it: the solver's, freed by the derived class)
  if (ctx_ != nullptr) SUNContext_Free(&ctx_);
}

void AdaptiveIntegrator::makeLinearSolver() {
  if (A_ != nullptr) return;
  A_ = SUNDenseMatrix(chart_.size(), chart_.size(), ctx_);
  LS_ = SUNLinSol_Dense(y_, A_, ctx_);
}

bool AdaptiveIntegrator::makeChartSolver(bool kinematicImplicit) {
  if (denseNewton_ || source_ == nullptr || source_->jacobianPattern() == nullptr) return false;
  if (A_ != nullptr) return true;
  kinematicImplicit_ = kinematicImplicit;
  A_ = makeChartMatrix(ctx_);
  LS_ = makeChartLinearSolver(ctx_, &newton_);
  return true;
}

int AdaptiveIntegrator::linearSystem(double t, N_Vector y, N_Vector fy, bool jok, int* jcur,
                                     double gamma) {
  try {
    // (the source's pattern) => the chart Newton system for it, made again when it changed
    const JacobianPattern* pattern = source_->jacobianPattern();
    if (pattern == nullptr)
      throw IntegrationError(std::string(name()) + ": the system lost its Jacobian pattern");
    if (newtonFor_ != pattern) {
      newton_ = std::make_unique<ChartNewtonSystem>(model_, *pattern, source_->jacobianBlocks(),
                                                    kinematicImplicit_);
      newtonFor_ = pattern;
      jok = false;
    }
    // (y) => q, v; (jok) => the blocks there, else F_q, F_v, K, G formed at (t, y, fy)
    const double* yv = N_VGetArrayPointer(y);
    chart_.scatter(yv, q_, v_);
    if (jok) {
      newton_->refreshBlocks(*source_, t, q_, v_);
      *jcur = 0;
    } else {
      a_ = Eigen::Map<const Eigen::VectorXd>(N_VGetArrayPointer(fy) + model_.nv, model_.nv);
      stats_.f_evals += newton_->form(*source_, t, chart_.origin(), yv, q_, a_);
      *jcur = 1;
    }
    // (gamma) => the reduced matrix's LU (a singular one fails the solver's setup, recoverably)
    newton_->factorise(gamma);
    return 0;
  } catch (...) {
    thrown_ = std::current_exception();
    return -1;
  }
}

int AdaptiveIntegrator::denseJacobian(double t, N_Vector y, N_Vector fy, SUNMatrix J, N_Vector work,
                                      Part part) {
  try {
    // (y) => q, v, the linearisation about them; (each column j) => y_j moved by
    // sqrt(eps) max(1, |y_j|), the part there, the quotient, y_j restored
    double* yv = N_VGetArrayPointer(y);
    const double* f0 = N_VGetArrayPointer(fy);
    const double* f1 = N_VGetArrayPointer(work);
    chart_.scatter(yv, q_, v_);
    const LinearisedScope linearised(*source_, t, q_, v_);
    const sunindextype n = SUNDenseMatrix_Columns(J);
    const double eps = std::sqrt(std::numeric_limits<double>::epsilon());
    for (sunindextype j = 0; j < n; ++j) {
      const double saved = yv[j], inc = eps * std::max(1.0, std::abs(saved));
      yv[j] = saved + inc;
      const int flag = rightHandSide(t, y, work, part);
      yv[j] = saved;
      if (flag != 0) return flag;
      double* col = SUNDenseMatrix_Column(J, j);
      for (sunindextype i = 0; i < n; ++i) col[i] = (f1[i] - f0[i]) / inc;
    }
    return 0;
  } catch (...) {
    thrown_ = std::current_exception();
    return -1;
  }
}

void AdaptiveIntegrator::solverError(const char* module, const char* function, const char* message) {
  error_ = std::string(module) + "::" + function + ": " + message;
}

int AdaptiveIntegrator::rightHandSide(double t, N_Vector y, N_Vector ydot, Part part) {
  try {
    const double* yv = N_VGetArrayPointer(y);
    double* out = N_VGetArrayPointer(ydot);
    // (y) => kinematic half chartRate(theta, v)
    if (part == Part::Dynamic) std::fill(out, out + model_.nv, 0.0);
    else chart_.kinematicRate(yv, out);
    if (part == Part::Kinematic) {
      std::fill(out + model_.nv, out + 2 * model_.nv, 0.0);
      return 0;
    }
    // (y) => q, v => a(t, q, v), the dynamic half
    chart_.scatter(yv, q_, v_);
    evaluate(*source_, t, q_, v_, a_);
    chart_.dynamicRate(a_, out);
    return 0;
  } catch (...) {
    thrown_ = std::current_exception();
    return -1;
  }
}

int AdaptiveIntegrator::rootFunctions(double t, N_Vector y, double* g) {
  try {
    chart_.scatter(N_VGetArrayPointer(y), q_, v_);
    source_->eventFunctions(t, q_, v_, std::span<double>(g, static_cast<std::size_t>(nroots_)));
    return 0;
  } catch (...) {
    thrown_ = std::current_exception();
    return -1;
  }
}

void AdaptiveIntegrator::step(AccelerationSource& system, double& t, Eigen::VectorXd& q, Eigen::VectorXd& v,
                              double h) {
  lastEvent_ = -1;
  // (t, q, v) => continue the solver's history, or re-initialise it at this state
  const double tol = 1e-9 * std::max(1.0, std::abs(t));
  const int roots = roots_ ? system.eventCount() : 0;
  const bool continues = initialised_ && source_ == &system && roots == nroots_ && std::abs(t - tLast_) <= tol &&
                         q == qLast_ && v == vLast_ && chart_.rotationExtent(N_VGetArrayPointer(y_)) < 1.0;
  source_ = &system;
  if (!continues) {
    nroots_ = roots;
    found_.assign(static_cast<std::size_t>(roots), 0);
    chart_.gather(q, v, N_VGetArrayPointer(y_));
    // (chart origin) => atol + rtol |q*| on the chart coordinates of plain joint coordinates
    double* atol = N_VGetArrayPointer(atol_);
    for (int i = 1; i < model_.nbodies; ++i)
      if (model_.jointNq[i] == model_.jointNv[i])
        for (int k = 0; k < model_.jointNv[i]; ++k)
          atol[model_.idxV[i] + k] = spec_.atol + spec_.rtol * std::abs(q[model_.idxQ[i] + k]);
    init(t, roots);
    initialised_ = true;
  }
  // (solver) => y at t + h, or at the first root before it
  IntegratorStats c0, c1;
  counters(c0);
  // (re-initialised) => the linear solver's Jacobian count restarts from 0 inside the next advance
  // (cvLsInitialize, arkLsInitialize, at the solver's first step), not at the re-initialisation
  if (!continues) c0.jac_evals = 0;
  double tret = t;
  error_.clear();
  const int flag = advance(t + h, tret);
  counters(c1);
  stats_.steps += c1.steps - c0.steps;
  stats_.jac_evals += c1.jac_evals - c0.jac_evals;
  stats_.newton_its += c1.newton_its - c0.newton_its;
  stats_.err_fails += c1.err_fails - c0.err_fails;
  stats_.factorisations += c1.factorisations - c0.factorisations;
  stats_.conv_fails += c1.conv_fails - c0.conv_fails;
  if (thrown_) {
    initialised_ = false;
    std::exception_ptr e = thrown_;
    thrown_ = nullptr;
    std::rethrow_exception(e);
  }
  if (flag < 0) {
    initialised_ = false;
    std::ostringstream m;
    m << name() << " failed at t = " << tret << " s (flag " << flag << ")" << (error_.empty() ? "" : ": ") << error_
      << "; try looser tolerances, a smaller max_step, or an implicit method (cvode_bdf, arkode_dirk)";
    throw IntegrationError(m.str());
  }
  chart_.scatter(N_VGetArrayPointer(y_), q, v);
  t = tret;
  if (rootReturn(flag)) {
    rootInfo(found_.data());
    for (int j = 0; j < nroots_; ++j)
      if (found_[static_cast<std::size_t>(j)] != 0) {
        lastEvent_ = j;
        break;
      }
  }
  // (after-step hook) => if it moved the state, the solver restarts from the moved state
  qOut_ = q;
  vOut_ = v;
  system.afterStep(t, q, v);
  if (q != qOut_ || v != vOut_) initialised_ = false;
  tLast_ = t;
  qLast_ = q;
  vLast_ = v;
}

}  // namespace yardsim::dynamics
