#include "forces/hydro/surface_growth.hpp"

#include <cmath>
#include <complex>

#include <Eigen/Eigenvalues>

namespace yardsim::forces::hydro {

SurfaceGrowth surfaceGrowth(const RankineTdModel& model) {
  const MixedProblem& pb = model.problem();
  const int nb = pb.bodyCount(), nf = pb.surfaceCount();
  const double g = model.settings().g;
  // (phi = e_j on the free surface, hull at rest) => column j of L: phi -> phi_z = -phi_n
  const Eigen::MatrixXd u =
      pb.solve(Eigen::MatrixXd::Zero(nb, nf), Eigen::MatrixXd::Identity(nf, nf));
  const Eigen::MatrixXd L = -u.bottomRows(nf);
  // (eigenvalue lambda of L) => s = +-i sqrt(g lambda) without damping: growth |Im sqrt(g lambda)|
  const Eigen::VectorXcd lambda = Eigen::EigenSolver<Eigen::MatrixXd>(L, false).eigenvalues();
  SurfaceGrowth out;
  out.panels = nf;
  out.rate = 0.0;
  for (Eigen::Index k = 0; k < lambda.size(); ++k) {
    const std::complex<double> w = std::sqrt(g * lambda[k]);
    if (std::abs(w.imag()) > out.rate) {
      out.rate = std::abs(w.imag());
      out.frequency = std::abs(w.real());
    }
  }
  // (uniform damping nu0) => every free solution times e^(-nu0 t)
  out.rate -= model.settings().freeSurface.surfaceDamping;
  return out;
}

}  // namespace yardsim::forces::hydro
