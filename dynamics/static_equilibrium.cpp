#include "dynamics/static_equilibrium.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

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
  // (trial q) => its residual, +inf where the system cannot evaluate it (far from anything)
  auto trialResidual = [&](Eigen::VectorXd& qq, Eigen::VectorXd& out) {
    try {
      const double r = residual(qq, out);
      return std::isfinite(r) ? r : std::numeric_limits<double>::infinity();
    } catch (const std::runtime_error&) {
      return std::numeric_limits<double>::infinity();
    }
  };
  EquilibriumResult result;
  result.residual = residual(q, a);
  double sigma = 0.0;
  int neutral = 0;  // accepted moves in a row that did not lower the residual
  while (result.residual > options.tolerance && result.iterations < options.maxIterations) {
    ++result.iterations;
    // (q) => J = da/dx, one tangent direction at a time
    for (Eigen::Index k = 0; k < nv; ++k) {
      e.setZero();
      e[k] = options.step;
      integrate(model, q, e, 1.0, qTrial);
      if (!std::isfinite(trialResidual(qTrial, aTrial))) aTrial = a;  // no information there
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
      bool descent = false;
      if (dx.allFinite()) {
        integrate(model, q, dx, 1.0, qTrial);
        normalizeConfiguration(model, qTrial);
        const double trial = trialResidual(qTrial, aTrial);
        // a descent, or (with sigma > 0) a move that changes nothing yet: falling onto a slack
        // rope leaves the residual at g until the rope bites; such moves keep their size and
        // are limited in number (a body with nothing under it falls forever)
        descent = trial < result.residual;
        accepted = descent || (sigma > 0.0 && neutral < options.maxNeutralSteps &&
                               trial <= result.residual * (1.0 + 1e-12));
      }
      if (accepted) {
        neutral = descent ? 0 : neutral + 1;
        if (descent) sigma = sigma * 0.1 < 1e-12 * scale ? 0.0 : sigma * 0.1;
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
