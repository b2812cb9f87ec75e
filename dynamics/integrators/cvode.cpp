#include "dynamics/integrators/cvode.hpp"

#include <cvode/cvode.h>
#include <cvode/cvode_ls.h>

namespace yardsim::dynamics {

namespace {
int rhs(double t, N_Vector y, N_Vector ydot, void* self) {
  return static_cast<AdaptiveIntegrator*>(self)->rightHandSide(t, y, ydot, AdaptiveIntegrator::Part::All);
}
int roots(double t, N_Vector y, double* g, void* self) {
  return static_cast<AdaptiveIntegrator*>(self)->rootFunctions(t, y, g);
}
int linSys(double t, N_Vector y, N_Vector fy, SUNMatrix, booleantype jok, booleantype* jcur,
           double gamma, void* self, N_Vector, N_Vector, N_Vector) {
  int current = 0;
  const int flag =
      static_cast<AdaptiveIntegrator*>(self)->linearSystem(t, y, fy, jok != 0, &current, gamma);
  *jcur = current != 0 ? SUNTRUE : SUNFALSE;
  return flag;
}
int jac(double t, N_Vector y, N_Vector fy, SUNMatrix J, void* self, N_Vector work, N_Vector,
        N_Vector) {
  return static_cast<AdaptiveIntegrator*>(self)->denseJacobian(t, y, fy, J, work,
                                                               AdaptiveIntegrator::Part::All);
}
void onError(int, const char* module, const char* function, char* message, void* self) {
  static_cast<AdaptiveIntegrator*>(self)->solverError(module, function, message);
}
}  // namespace

Cvode::Cvode(const Model& model, const IntegratorSpec& spec)
    : AdaptiveIntegrator(model, spec), bdf_(spec.method != "cvode_adams") {}

Cvode::~Cvode() {
  if (mem_ != nullptr) CVodeFree(&mem_);
}

void Cvode::init(double t, int nroots) {
  // (y at t) => CVODE created once (tolerances, Newton's linear solver, order, step bound), then
  // re-initialised. The linear solver: with lumped lines (a Jacobian pattern) the chart Newton
  // system (sparse, chart_newton_system.hpp) through a linear system function, else dense
  if (mem_ == nullptr) {
    mem_ = CVodeCreate(bdf_ ? CV_BDF : CV_ADAMS, ctx_);
    CVodeInit(mem_, rhs, t, y_);
    CVodeSetUserData(mem_, this);
    CVodeSetErrHandlerFn(mem_, onError, this);
    const bool sparse = makeChartSolver(true);
    if (!sparse) makeLinearSolver();
    CVodeSetLinearSolver(mem_, LS_, A_);
    // (dense, a catenary line) => its analytic linearisation in the difference quotients
    if (!sparse && denseJacobianWanted()) CVodeSetJacFn(mem_, jac);
    if (sparse) {
      CVodeSetLinSysFn(mem_, linSys);
      // (lumped lines: their blocks, and their end nodes' couplings to the bodies, are
      // re-evaluated in closed form at every setup, so only the rest of the rigid dofs' columns
      // age) => a coloured Jacobian after a failed Newton solve or every linesJacobianAge_
      // (1000) steps, instead of CVODE's 51 (docs/performance.md, "The slope in nodes, third
      // pass")
      CVodeSetJacEvalFrequency(mem_, linesJacobianAge_);
    }
    if (spec_.maxOrder > 0) CVodeSetMaxOrd(mem_, spec_.maxOrder);
    if (spec_.maxStep > 0) CVodeSetMaxStep(mem_, spec_.maxStep);
    CVodeSetMaxNumSteps(mem_, 1000000);
  } else {
    CVodeReInit(mem_, t, y_);
  }
  CVodeSVtolerances(mem_, spec_.rtol, atol_);
  CVodeRootInit(mem_, nroots, nroots > 0 ? roots : nullptr);
}

int Cvode::advance(double tout, double& tret) {
  CVodeSetStopTime(mem_, tout);
  return CVode(mem_, tout, y_, &tret, CV_NORMAL);
}

bool Cvode::rootReturn(int flag) const { return flag == CV_ROOT_RETURN; }

void Cvode::rootInfo(int* found) { CVodeGetRootInfo(mem_, found); }

void Cvode::counters(IntegratorStats& s) {
  long steps = 0, jac = 0, nni = 0, etf = 0, setups = 0, ncf = 0;
  if (mem_ != nullptr) {
    CVodeGetNumSteps(mem_, &steps);
    CVodeGetNumJacEvals(mem_, &jac);
    CVodeGetNumNonlinSolvIters(mem_, &nni);
    CVodeGetNumErrTestFails(mem_, &etf);
    CVodeGetNumLinSolvSetups(mem_, &setups);
    CVodeGetNumNonlinSolvConvFails(mem_, &ncf);
  }
  s.steps = steps;
  s.jac_evals = jac;
  s.newton_its = nni;
  s.err_fails = etf;
  s.factorisations = setups;
  s.conv_fails = ncf;
}

}  // namespace yardsim::dynamics
