#include "dynamics/static_equilibrium.hpp"

#include <Eigen/QR>
#include <algorithm>

#include "dynamics/configuration.hpp"

namespace yardsim::dynamics {

EquilibriumResult solveStaticEquilibrium(const Model& model, AccelerationSource& system, double t,
                                         Eigen::VectorXd& q, const EquilibriumOptions& options) {
  const Eigen::Index nv = model.nv;
  Eigen::VectorXd v = Eigen::VectorXd::Zero(nv), a(nv), aTrial(nv), dx(nv), e(nv), qTrial(q.size());
  Eigen::MatrixXd J(nv, nv);
  // (q) => max |a| at rest, after the system's own step hook (loop projection)
  auto residual = [&](Eigen::VectorXd& qq, Eigen::VectorXd& out) {
    v.setZero();
    system.afterStep(t, qq, v);
    v.setZero();
    system.acceleration(t, qq, v, out);
    return out.size() ? out.cwiseAbs().maxCoeff() : 0.0;
  };
  EquilibriumResult result;
  result.residual = residual(q, a);
  double sigma = 0.0;
  while (result.residual > options.tolerance && result.iterations < options.maxIterations) {
    ++result.iterations;
    // (q) => J = da/dx, one tangent direction at a time
    for (Eigen::Index k = 0; k < nv; ++k) {
      e.setZero();
      e[k] = options.step;
      integrate(model, q, e, 1.0, qTrial);
      residual(qTrial, aTrial);
      J.col(k) = (aTrial - a) / options.step;
    }
    const double scale = std::max(1.0, J.cwiseAbs().maxCoeff());  // 1/s^2
    // (J, a) => a step of (J - sigma I) dx = -a: Newton's (minimum-norm) when sigma = 0, a
    // step along the accelerations when J vanishes (a slack rope); sigma grows until the step
    // is accepted, then shrinks again (Levenberg-Marquardt on the residual)
    bool accepted = false;
    for (int tries = 0; tries < 60 && !accepted; ++tries) {
      Eigen::MatrixXd A = J;
      A.diagonal().array() -= sigma;
      dx = A.completeOrthogonalDecomposition().solve(-a);
      if (dx.allFinite()) {
        integrate(model, q, dx, 1.0, qTrial);
        normalizeConfiguration(model, qTrial);
        const double trial = residual(qTrial, aTrial);
        // a descent, or (with sigma > 0) a move that changes nothing yet: falling onto a slack
        // rope leaves the residual at g until the rope bites
        accepted = trial < result.residual || (sigma > 0.0 && trial <= result.residual * (1.0 + 1e-12));
      }
      if (accepted) {
        sigma = sigma * 0.1 < 1e-12 * scale ? 0.0 : sigma * 0.1;
      } else {
        sigma = sigma == 0.0 ? 1e-6 * scale : sigma * 10.0;
      }
    }
    if (!accepted) break;  // no descent: the best configuration found is kept
    q = qTrial;
    result.residual = residual(q, a);
  }
  result.converged = result.residual <= options.tolerance;
  return result;
}

}  // namespace yardsim::dynamics
