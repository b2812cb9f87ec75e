#include "dynamics/integrators/sundials_chart_solver.hpp"

#include <nvector/nvector_serial.h>

namespace yardsim::dynamics {

namespace {

using Holder = const std::unique_ptr<ChartNewtonSystem>;

SUNMatrix_ID matrixId(SUNMatrix) {
  return SUNMATRIX_CUSTOM;
}
void matrixDestroy(SUNMatrix A) {
  SUNMatFreeEmpty(A);
}

SUNLinearSolver_Type solverType(SUNLinearSolver) {
  return SUNLINEARSOLVER_DIRECT;
}
SUNLinearSolver_ID solverId(SUNLinearSolver) {
  return SUNLINEARSOLVER_CUSTOM;
}
int solverFree(SUNLinearSolver S) {
  SUNLinSolFreeEmpty(S);
  return SUNLS_SUCCESS;
}
// (the linear system function has factorised) => success, or a recoverable failure when singular
int solverSetup(SUNLinearSolver S, SUNMatrix) {
  const auto& system = *static_cast<Holder*>(S->content);
  return system && system->factorised() ? SUNLS_SUCCESS : SUNLS_LUFACT_FAIL;
}
// (b) => x = (I - gamma J)^-1 b by the system's elimination
int solverSolve(SUNLinearSolver S, SUNMatrix, N_Vector x, N_Vector b, realtype) {
  const auto& system = *static_cast<Holder*>(S->content);
  if (!system || !system->factorised()) return SUNLS_LUFACT_FAIL;
  system->solve(N_VGetArrayPointer(b), N_VGetArrayPointer(x));
  return SUNLS_SUCCESS;
}

}  // namespace

SUNMatrix makeChartMatrix(SUNContext ctx) {
  SUNMatrix A = SUNMatNewEmpty(ctx);
  A->ops->getid = matrixId;
  A->ops->destroy = matrixDestroy;
  return A;
}

SUNLinearSolver makeChartLinearSolver(SUNContext ctx,
                                      const std::unique_ptr<ChartNewtonSystem>* system) {
  SUNLinearSolver S = SUNLinSolNewEmpty(ctx);
  S->ops->gettype = solverType;
  S->ops->getid = solverId;
  S->ops->setup = solverSetup;
  S->ops->solve = solverSolve;
  S->ops->free = solverFree;
  S->content = const_cast<std::unique_ptr<ChartNewtonSystem>*>(system);
  return S;
}

}  // namespace yardsim::dynamics
