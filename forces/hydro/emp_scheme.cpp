#include "forces/hydro/emp_scheme.hpp"

#include <cmath>
#include <limits>

namespace yardsim::forces::hydro {

FreeSurfaceState quietSurface(const RankineTdModel& model) {
  const int nf = model.problem().surfaceCount();
  return {Eigen::VectorXd::Zero(nf), Eigen::VectorXd::Zero(nf)};
}

EmpScratch makeEmpScratch(const RankineTdModel& model) {
  const MixedProblem& pb = model.problem();
  return {Eigen::VectorXd::Zero(pb.surfaceCount()), Eigen::VectorXd::Zero(pb.surfaceCount())};
}

Vector6 empStep(const RankineTdModel& model, double dt,
                const Eigen::Ref<const Eigen::VectorXd>& bodyNormalVelocity,
                const Eigen::Ref<const Eigen::VectorXd>& memoryNeumann, FreeSurfaceState& state,
                EmpScratch& scratch) {
  const MixedProblem& pb = model.problem();
  const int nb = pb.bodyCount(), nf = pb.surfaceCount();
  const double g = model.settings().g;
  // (a^n, phi^n) => phi_n,f, the last Nf rows of the solution map's product (phi_b is not
  // needed); phi_z = -phi_n on the free surface (normal -z)
  const Eigen::MatrixXd& map = pb.solutionMap();
  scratch.phiN.noalias() = map.bottomLeftCorner(nf, nb) * bodyNormalVelocity;
  scratch.phiN.noalias() += map.bottomRightCorner(nf, nf) * state.phi;
  const auto phiZ = -scratch.phiN.array();
  const auto nu = model.damping().array();
  // (phi_z^n, zeta^n, phi^n) => zeta^n+1 (kinematic, explicit)
  scratch.zetaOld = state.zeta;
  state.zeta.array() +=
      dt * (phiZ - 2.0 * nu * scratch.zetaOld.array() + nu * nu / g * state.phi.array());
  // (zeta^n, zeta^n+1, a_t^n) => F^M(t_n); then phi^n+1 (dynamic, implicit)
  // (the Dirichlet value -g (zeta^n + zeta^n+1) / 2 in the scratch buffer: no temporary)
  scratch.zetaOld = -0.5 * g * (scratch.zetaOld + state.zeta);
  Vector6 f;
  f.noalias() = model.forceFromSurface() * scratch.zetaOld;
  if (memoryNeumann.size() == nb) f.noalias() += model.forceFromBody() * memoryNeumann;
  state.phi -= dt * g * state.zeta;
  return f;
}

EmpLimit empLimit(const RankineTdModel& model, int iterations) {
  const MixedProblem& pb = model.problem();
  const int nf = pb.surfaceCount();
  EmpLimit out;
  out.smallestPanel = std::numeric_limits<double>::infinity();
  for (const Panel& p : pb.surface())
    out.smallestPanel = std::min(out.smallestPanel, std::sqrt(p.area));
  // (phi on the free surface, hull at rest) => phi_z = -A_ff phi; power iteration from a
  // deterministic alternating start (rich in the shortest waves the mesh carries)
  const auto toPhiN = pb.solutionMap().bottomRightCorner(nf, nf);
  Eigen::VectorXd p(nf), w(nf);
  for (int k = 0; k < nf; ++k) p(k) = (k % 2 == 0 ? 1.0 : -1.0) * (1.0 + 0.1 * std::sin(1.7 * k));
  p /= p.norm();
  double lambda = 0.0;
  for (int it = 0; it < iterations; ++it) {
    w.noalias() = -(toPhiN * p);
    lambda = p.dot(w);
    p = w / w.norm();
  }
  out.lambdaMax = lambda;
  out.dtMax = lambda > 0.0 ? 2.0 / std::sqrt(model.settings().g * lambda) : 0.0;
  return out;
}

}  // namespace yardsim::forces::hydro
