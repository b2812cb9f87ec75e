#include "dynamics/integrators/arkode.hpp"

#include <arkode/arkode_arkstep.h>
#include <arkode/arkode_ls.h>

namespace yardsim::dynamics {

namespace {
using Part = AdaptiveIntegrator::Part;
template <Part P>
int rhs(double t, N_Vector y, N_Vector ydot, void* self) {
  return static_cast<AdaptiveIntegrator*>(self)->rightHandSide(t, y, ydot, P);
}
int roots(double t, N_Vector y, double* g, void* self) {
  return static_cast<AdaptiveIntegrator*>(self)->rootFunctions(t, y, g);
}
int linSys(double t, N_Vector y, N_Vector fy, SUNMatrix, SUNMatrix, booleantype jok,
           booleantype* jcur, double gamma, void* self, N_Vector, N_Vector, N_Vector) {
  int current = 0;
  const int flag =
      static_cast<AdaptiveIntegrator*>(self)->linearSystem(t, y, fy, jok != 0, &current, gamma);
  *jcur = current != 0 ? SUNTRUE : SUNFALSE;
  return flag;
}
template <Part P>
int jac(double t, N_Vector y, N_Vector fy, SUNMatrix J, void* self, N_Vector work, N_Vector,
        N_Vector) {
  return static_cast<AdaptiveIntegrator*>(self)->denseJacobian(t, y, fy, J, work, P);
}
void onError(int, const char* module, const char* function, char* message, void* self) {
  static_cast<AdaptiveIntegrator*>(self)->solverError(module, function, message);
}
Arkode::Kind kindOf(const std::string& method) {
  if (method == "arkode_dirk") return Arkode::Kind::Dirk;
  if (method == "arkode_imex") return Arkode::Kind::Imex;
  return Arkode::Kind::Erk;
}
}  // namespace

Arkode::Arkode(const Model& model, const IntegratorSpec& spec)
    : AdaptiveIntegrator(model, spec), kind_(kindOf(spec.method)) {}

Arkode::~Arkode() {
  if (mem_ != nullptr) ARKStepFree(&mem_);
}

std::string_view Arkode::name() const {
  switch (kind_) {
    case Kind::Dirk: return "arkode_dirk";
    case Kind::Imex: return "arkode_imex";
    case Kind::Erk: break;
  }
  return "arkode_erk";
}

void Arkode::init(double t, int nroots) {
  // (kind) => explicit part fe, implicit part fi
  ARKRhsFn fe = nullptr, fi = nullptr;
  switch (kind_) {
    case Kind::Erk: fe = rhs<Part::All>; break;
    case Kind::Dirk: fi = rhs<Part::All>; break;
    case Kind::Imex:
      fe = rhs<Part::Kinematic>;
      fi = rhs<Part::Dynamic>;
      break;
  }
  // (y at t) => ARKStep created once (tolerances, order 4, Newton when implicit: with lumped lines
  // the chart Newton system, its kinematic half implicit for DIRK and explicit for IMEX; else
  // dense), then re-initialised
  if (mem_ == nullptr) {
    mem_ = ARKStepCreate(fe, fi, t, y_, ctx_);
    ARKStepSetUserData(mem_, this);
    ARKStepSetErrHandlerFn(mem_, onError, this);
    ARKStepSetOrder(mem_, 4);
    if (kind_ != Kind::Erk) {
      const bool sparse = makeChartSolver(kind_ == Kind::Dirk);
      if (!sparse) makeLinearSolver();
      ARKStepSetLinearSolver(mem_, LS_, A_);
      // (dense, a catenary line) => its analytic linearisation in the difference quotients of fi
      if (!sparse && denseJacobianWanted())
        ARKStepSetJacFn(mem_, kind_ == Kind::Dirk ? jac<Part::All> : jac<Part::Dynamic>);
      if (sparse) ARKStepSetLinSysFn(mem_, linSys);
    }
    if (spec_.maxStep > 0) ARKStepSetMaxStep(mem_, spec_.maxStep);
    ARKStepSetMaxNumSteps(mem_, 1000000);
  } else {
    ARKStepReInit(mem_, fe, fi, t, y_);
  }
  ARKStepSVtolerances(mem_, spec_.rtol, atol_);
  ARKStepRootInit(mem_, nroots, nroots > 0 ? roots : nullptr);
}

int Arkode::advance(double tout, double& tret) {
  ARKStepSetStopTime(mem_, tout);
  return ARKStepEvolve(mem_, tout, y_, &tret, ARK_NORMAL);
}

bool Arkode::rootReturn(int flag) const { return flag == ARK_ROOT_RETURN; }

void Arkode::rootInfo(int* found) { ARKStepGetRootInfo(mem_, found); }

void Arkode::counters(IntegratorStats& s) {
  long steps = 0, jac = 0, nni = 0, etf = 0, setups = 0, ncf = 0;
  if (mem_ != nullptr) {
    ARKStepGetNumSteps(mem_, &steps);
    if (kind_ != Kind::Erk) {
      ARKStepGetNumJacEvals(mem_, &jac);
      ARKStepGetNumNonlinSolvIters(mem_, &nni);
      ARKStepGetNumLinSolvSetups(mem_, &setups);
      ARKStepGetNumNonlinSolvConvFails(mem_, &ncf);
    }
    ARKStepGetNumErrTestFails(mem_, &etf);
  }
  s.steps = steps;
  s.jac_evals = jac;
  s.newton_its = nni;
  s.err_fails = etf;
  s.factorisations = setups;
  s.conv_fails = ncf;
}

}  // namespace yardsim::dynamics
