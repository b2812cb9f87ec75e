#pragma once
// Time marching of the linear free surface by the explicit-kinematic / implicit-dynamic scheme
// ("emp", symplectic Euler) on the panels of a RankineTdModel. Per step t_n -> t_n+1 = t_n + dt:
//   1. phi_z^n on the free surface from the mixed problem with phi^n there and the hull's
//      normal velocity a^n (the last Nf rows of the solution map's product, mixed_problem.hpp);
//   2. zeta^n+1 = zeta^n + dt (phi_z^n - 2 nu zeta^n + nu^2 phi^n / g)      (explicit, kinematic)
//   3. phi^n+1  = phi^n - dt g zeta^n+1                                     (implicit, dynamic)
// zeta lives at the half steps (zeta^n ~ zeta(t_n - dt/2), the Stormer-Verlet reading of
// symplectic Euler), so the memory force at t_n takes the Dirichlet value -g (zeta^n + zeta^n+1)/2:
//   F^M(t_n) = forceFromSurface (-g (zeta^n + zeta^n+1) / 2) + forceFromBody a_t^n
// (the dphi^M/dt problem through the adjoint maps of the same solution map; a_t the Neumann
// value of dphi^M/dt on the hull: 0 for radiation, -d^2 phi_I/(dn dt) for diffraction).
// Without damping the scheme is stable for g lambda_max dt^2 <= 4, lambda_max the largest
// eigenvalue of the discrete operator phi -> phi_z on the free surface (hull at rest).
// Units: zeta m, phi m^2/s, a m/s, a_t m/s^2, dt s, force W axes about the body origin, N and N m.
#include <Eigen/Core>

#include "forces/hydro/rankine_td_model.hpp"

namespace yardsim::forces::hydro {

/// The solver's state: a plain value, one entry per free-surface panel (checkpointed as is).
struct FreeSurfaceState {
  Eigen::VectorXd zeta;  ///< elevation, m (at the half step before the state's time)
  Eigen::VectorXd phi;   ///< potential of the disturbance (radiation + diffraction), m^2/s
};

/// (model) => a quiet free surface.
FreeSurfaceState quietSurface(const RankineTdModel& model);

/// Buffers one emp step writes; made once per model.
struct EmpScratch {
  Eigen::VectorXd phiN;     ///< Nf, phi_n on the free surface, m/s
  Eigen::VectorXd zetaOld;  ///< Nf
};
EmpScratch makeEmpScratch(const RankineTdModel& model);

using Vector6 = Eigen::Matrix<double, 6, 1>;

/// (model, dt, hull normal velocity a^n (Nb), Neumann value of dphi^M/dt a_t^n (Nb, or size 0 for
/// none), state at t_n, scratch) => state at t_n+1; returns F^M(t_n). Allocation-free.
Vector6 empStep(const RankineTdModel& model, double dt,
                const Eigen::Ref<const Eigen::VectorXd>& bodyNormalVelocity,
                const Eigen::Ref<const Eigen::VectorXd>& memoryNeumann, FreeSurfaceState& state,
                EmpScratch& scratch);

struct EmpLimit {
  double lambdaMax = 0.0;      ///< 1/m, largest eigenvalue of phi -> phi_z (power iteration)
  double dtMax = 0.0;          ///< s, 2 / sqrt(g lambda_max)
  double smallestPanel = 0.0;  ///< m, sqrt of the smallest free-surface panel area
};

/// (model) => the emp stability limit of its free-surface mesh (about 3.44 / h for constant
/// panels of size h, i.e. dt <= 1.08 sqrt(h / g)). Costs `iterations` solves.
EmpLimit empLimit(const RankineTdModel& model, int iterations = 200);

}  // namespace yardsim::forces::hydro
