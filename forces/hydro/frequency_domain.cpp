#include "forces/hydro/frequency_domain.hpp"

#include <cmath>
#include <stdexcept>

#include <Eigen/LU>

#include "forces/airy_waves.hpp"
#include "forces/hydro/incident_kinematics.hpp"

namespace yardsim::forces::hydro {

using Complex = std::complex<double>;

FrequencyDomainSolver::FrequencyDomainSolver(const RankineTdModel& model) : model_(model) {
  // (the mixed problem's solution map: M^-1 R_b, M^-1 R_f) => M^-1 R_b N
  const MixedProblem& pb = model.problem();
  fromModes_ = pb.solutionMap().leftCols(pb.bodyCount()) * model.modes();
}

FrequencyResponse FrequencyDomainSolver::solve(double omega,
                                               const std::vector<double>& headings) const {
  if (!(omega > 0.0)) throw std::invalid_argument("frequency domain: omega must be > 0");
  const MixedProblem& pb = model_.problem();
  const int nb = pb.bodyCount(), nf = pb.surfaceCount(), nh = static_cast<int>(headings.size());
  const RankineTdSettings& set = model_.settings();
  const double g = set.g, rho = set.rho, h = set.depth;
  const Complex i(0.0, 1.0);
  const auto fromBody = pb.solutionMap().leftCols(nb);      // M^-1 R_b
  const auto fromSurface = pb.solutionMap().rightCols(nf);  // M^-1 R_f
  // (G_ff, nu) => G_ff + diag((w - i nu)^2 / g), factorised
  Eigen::MatrixXcd system = fromSurface.bottomRows(nf).cast<Complex>();
  for (int k = 0; k < nf; ++k) {
    const Complex w(omega, -model_.damping()[k]);
    system(k, k) += w * w / g;
  }
  const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(system);
  // (data a on the hull, columns) => p = -(G_ff + kappa)^-1 G_fb a, then phi_b = G_bb a + G_bf p;
  // here the columns: 6 radiation modes (a = i w N_j) and one diffraction problem per heading
  Eigen::MatrixXcd a(nb, nh), fk(nb, nh);
  Eigen::MatrixXcd gA(pb.size(), 6 + nh);
  gA.leftCols(6) = i * omega * fromModes_.cast<Complex>();
  const double k = waveNumber(omega, h, g);
  for (int c = 0; c < nh; ++c) {
    const Vector3 e(std::cos(headings[static_cast<std::size_t>(c)]),
                    std::sin(headings[static_cast<std::size_t>(c)]), 0.0);
    for (int p = 0; p < nb; ++p) {
      // (incident wave of unit amplitude at the panel) => -dphi_I/dn and phi_I
      const Panel& q = pb.body()[static_cast<std::size_t>(p)];
      const double zc = q.centroid.z();
      const auto [cc, sc] = depthFactors(k, zc, h);
      const Complex phase = std::exp(-i * k * q.centroid.dot(e));
      a(p, c) = -(g * k / omega) * phase * (cc * q.normal.dot(e) + i * sc * q.normal.z());
      fk(p, c) = i * (g / omega) * cc * phase;
    }
  }
  gA.rightCols(nh) = fromBody.cast<Complex>() * a;
  const Eigen::MatrixXcd p = lu.solve(-gA.bottomRows(nf));
  const Eigen::MatrixXcd phiB = gA.topRows(nb) + fromSurface.topRows(nb).cast<Complex>() * p;
  // (phi on the hull) => F = i w rho sum phi N A
  Eigen::MatrixXd weights(nb, 6);
  for (int q = 0; q < nb; ++q)
    weights.row(q) = rho * pb.body()[static_cast<std::size_t>(q)].area * model_.modes().row(q);
  const Eigen::MatrixXcd force = i * omega * weights.transpose().cast<Complex>() * phiB;
  const Eigen::MatrixXcd forceFk = i * omega * weights.transpose().cast<Complex>() * fk;
  FrequencyResponse out;
  out.omega = omega;
  out.addedMass = force.leftCols(6).real() / (omega * omega);
  out.damping = -force.leftCols(6).imag() / omega;
  for (int c = 0; c < nh; ++c) {
    out.froudeKrylov.push_back(forceFk.col(c));
    out.excitation.push_back(force.col(6 + c) + forceFk.col(c));
  }
  return out;
}

Eigen::Matrix<Complex, 6, 1> responseAmplitude(const Eigen::Matrix<double, 6, 6>& mass,
                                               const Eigen::Matrix<double, 6, 6>& restoring,
                                               const Eigen::Matrix<double, 6, 6>& extraDamping,
                                               const FrequencyResponse& r, std::size_t heading,
                                               const std::vector<int>& freeModes) {
  if (heading >= r.excitation.size())
    throw std::invalid_argument("responseAmplitude: no such heading");
  // (the free rows and columns of -w^2 (M + A) + i w B + C) => their solve against X
  const int n = static_cast<int>(freeModes.size());
  const double w = r.omega;
  Eigen::MatrixXcd z(n, n);
  Eigen::VectorXcd x(n);
  for (int a = 0; a < n; ++a) {
    const int i = freeModes[static_cast<std::size_t>(a)];
    x[a] = r.excitation[heading][i];
    for (int b = 0; b < n; ++b) {
      const int j = freeModes[static_cast<std::size_t>(b)];
      z(a, b) = Complex(-w * w * (mass(i, j) + r.addedMass(i, j)) + restoring(i, j),
                        w * (r.damping(i, j) + extraDamping(i, j)));
    }
  }
  const Eigen::VectorXcd xi = z.partialPivLu().solve(x);
  Eigen::Matrix<Complex, 6, 1> out = Eigen::Matrix<Complex, 6, 1>::Zero();
  for (int a = 0; a < n; ++a) out[freeModes[static_cast<std::size_t>(a)]] = xi[a];
  return out;
}

}  // namespace yardsim::forces::hydro
