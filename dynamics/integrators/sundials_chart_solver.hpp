#pragma once
// A ChartNewtonSystem (chart_newton_system.hpp) seen by SUNDIALS' matrix-based linear solver
// interface (CVODE, ARKODE): a SUNMatrix that only stands for it (an id: the integrator's linear
// system function, CVodeSetLinSysFn / ARKStepSetLinSysFn, forms and factorises the system, CVODE
// only hands the matrix along) and a direct SUNLinearSolver whose setup reports that
// factorisation and whose solve is the system's. Not the matrix-embedded kind
// (SUNLINEARSOLVER_MATRIX_EMBEDDED): CVODE and ARKODE never call its setup, so it would get
// neither their Jacobian-reuse decisions (jok, jcur) nor a fresh Jacobian after a failed Newton
// solve, nor the correction for a changed gamma (docs/integrators.md).
#include <memory>

#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>

#include "dynamics/integrators/chart_newton_system.hpp"

namespace yardsim::dynamics {

// (context) => the stand-in matrix (SUNMATRIX_CUSTOM, no data); SUNMatDestroy frees it
SUNMatrix makeChartMatrix(SUNContext ctx);
// (context, where the system lives: it may be remade, the place stays) => the linear solver:
// setup fails (recoverably) when the last factorisation did, solve is system->solve(b) => x;
// SUNLinSolFree frees the solver, not the system
SUNLinearSolver makeChartLinearSolver(SUNContext ctx,
                                      const std::unique_ptr<ChartNewtonSystem>* system);

}  // namespace yardsim::dynamics
