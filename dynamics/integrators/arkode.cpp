#include "dynamics/integrators/arkode.hpp"

#include <arkode/arkode_arkstep.h>

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
  // (y at t) => ARKStep created once (tolerances, order 4, dense Newton when implicit), then re-initialised
  if (mem_ == nullptr) {
    mem_ = ARKStepCreate(fe, fi, t, y_, ctx_);
    ARKStepSetUserData(mem_, this);
    ARKStepSetErrHandlerFn(mem_, onError, this);
    ARKStepSetOrder(mem_, 4);
    if (kind_ != Kind::Erk) {
      makeLinearSolver();
      ARKStepSetLinearSolver(mem_, LS_, A_);
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
  long steps = 0, jac = 0, nni = 0, etf = 0;
  if (mem_ != nullptr) {
    ARKStepGetNumSteps(mem_, &steps);
    if (kind_ != Kind::Erk) {
      ARKStepGetNumJacEvals(mem_, &jac);
      ARKStepGetNumNonlinSolvIters(mem_, &nni);
    }
    ARKStepGetNumErrTestFails(mem_, &etf);
  }
  s.steps = steps;
  s.jac_evals = jac;
  s.newton_its = nni;
  s.err_fails = etf;
}

}  // namespace yardsim::dynamics
