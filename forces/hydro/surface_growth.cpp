#include "forces/hydro/surface_growth.hpp"

#include <cmath>
#include <complex>
#include <limits>
#include <utility>

#include "forces/hydro/dense_eigenvalues.hpp"

namespace yardsim::forces::hydro {

SurfaceGrowth surfaceGrowth(const RankineTdModel& model, double dt) {
  const MixedProblem& pb = model.problem();
  const int nf = pb.surfaceCount();
  const double g = model.settings().g;
  // (phi = e_j on the free surface, hull at rest) => column j of L: phi -> phi_z = -phi_n
  Eigen::MatrixXd L = -pb.solutionMap().bottomRightCorner(nf, nf);
  const Eigen::VectorXcd lambda = denseEigenvalues(std::move(L));
  const double nu0 = model.settings().freeSurface.surfaceDamping;
  SurfaceGrowth out;
  out.panels = nf;
  out.rate = -std::numeric_limits<double>::infinity();
  for (Eigen::Index k = 0; k < lambda.size(); ++k) {
    // (lambda, nu0) => the mode's 2 x 2 system on [zeta; phi]: continuous, or one emp step
    const std::complex<double> c = lambda[k] + nu0 * nu0 / g;
    std::complex<double> m00, m01, m10, m11;
    if (dt > 0.0) {
      m00 = 1.0 - 2.0 * nu0 * dt;
      m01 = dt * c;
      m10 = -g * dt * m00;
      m11 = 1.0 - g * dt * dt * c;
    } else {
      m00 = -2.0 * nu0;
      m01 = c;
      m10 = -g;
      m11 = 0.0;
    }
    const std::complex<double> tr = m00 + m11,
                               root = std::sqrt(tr * tr - 4.0 * (m00 * m11 - m01 * m10));
    for (const std::complex<double> z : {0.5 * (tr + root), 0.5 * (tr - root)}) {
      // (eigenvalue) => rate and frequency: Re s, |Im s|; or ln|z| / dt, |arg z| / dt
      const double rate = dt > 0.0 ? std::log(std::abs(z)) / dt : z.real();
      if (rate > out.rate) {
        out.rate = rate;
        out.frequency = dt > 0.0 ? std::abs(std::arg(z)) / dt : std::abs(z.imag());
      }
    }
  }
  return out;
}

}  // namespace yardsim::forces::hydro
