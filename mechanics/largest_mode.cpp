#include "mechanics/largest_mode.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCore>

#include "dynamics/configuration.hpp"

namespace yardsim::mechanics {

namespace {

using Sparse = Eigen::SparseMatrix<double>;

constexpr int kKrylov = 60;    // Arnoldi vectors per cycle
constexpr int kRestarts = 12;  // cycles at most
constexpr double kTol = 1e-3;  // Ritz residual relative to |lambda| that ends the cycles

// (kernel, q0, v0, pattern, step) => A_q, A_v on the pattern by central differences per colour
void linearise(dynamics::MultibodySystem& kernel, const dynamics::Model& model,
               const Eigen::VectorXd& q0, const Eigen::VectorXd& v0,
               const dynamics::JacobianPattern& pattern, double step, Sparse& Aq, Sparse& Av) {
  const int nv = model.nv;
  const dynamics::ColumnColouring colouring = dynamics::colourColumns(pattern);
  std::vector<Eigen::Triplet<double>> tq, tv;
  Eigen::VectorXd d(nv), q(model.nq), v(nv), ap(nv), am(nv);
  // (columns of one colour, ap, am) => their entries on the pattern's rows
  auto scatter = [&](const std::vector<int>& cols, std::vector<Eigen::Triplet<double>>& out) {
    for (int j : cols)
      for (int i : pattern.rows[static_cast<std::size_t>(j)])
        out.emplace_back(i, j, (ap[i] - am[i]) / (2.0 * step));
  };
  for (const std::vector<int>& cols : colouring.columns) {
    // (one colour) => its columns of A_q: every dof of the colour moved at once, both ways
    for (int side = 0; side < 2; ++side) {
      d.setZero();
      for (int j : cols) d[j] = side == 0 ? step : -step;
      dynamics::integrate(model, q0, d, 1.0, q);
      kernel.acceleration(0.0, q, v0, side == 0 ? ap : am);
    }
    scatter(cols, tq);
    // (one colour) => its columns of A_v
    for (int side = 0; side < 2; ++side) {
      v = v0;
      for (int j : cols) v[j] += side == 0 ? step : -step;
      kernel.acceleration(0.0, q0, v, side == 0 ? ap : am);
    }
    scatter(cols, tv);
  }
  Aq.resize(nv, nv);
  Av.resize(nv, nv);
  Aq.setFromTriplets(tq.begin(), tq.end());
  Av.setFromTriplets(tv.begin(), tv.end());
}

}  // namespace

LargestMode largestMode(dynamics::MultibodySystem& kernel, const dynamics::Model& model,
                        const Eigen::VectorXd& q0, const Eigen::VectorXd& v0,
                        const dynamics::JacobianPattern& pattern, double step) {
  const int nv = model.nv, n = 2 * nv;
  Sparse Aq, Av;
  linearise(kernel, model, q0, v0, pattern, step, Aq, Av);
  // (J, with omega^2 as large as the diagonal of A_q) => J_s = D J D^-1, D = diag(s I, I), s the
  // square root of that diagonal's largest modulus: the same eigenvalues, but for the stiff modes
  // a nearly normal matrix ([0 s; -omega^2/s 0] for one of them), where J's companion form is far
  // from normal and a small Ritz residual can leave the Ritz value several per cent off (seen:
  // 23,592 rad/s with a real part of 1,624 against the eigenvalue's 22,467, residual 2.4e-5)
  double diag = 1.0;
  for (int k = 0; k < Aq.outerSize(); ++k)
    for (Sparse::InnerIterator it(Aq, k); it; ++it)
      if (it.row() == it.col()) diag = std::max(diag, std::abs(it.value()));
  const double s = std::sqrt(diag);
  // (x) => J_s x = [s x_v; A_q x_q / s + A_v x_v]
  auto apply = [&](const Eigen::VectorXd& x, Eigen::VectorXd& y) {
    y.head(nv) = s * x.tail(nv);
    y.tail(nv) = (Aq * x.head(nv)) / s + Av * x.tail(nv);
  };
  // (a fixed pseudo-random start: no mode is missed by symmetry) => x
  Eigen::VectorXd x(n);
  std::uint64_t seed = 0x9E3779B97F4A7C15ull;
  for (int i = 0; i < n; ++i) {
    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
    x[i] = static_cast<double>(seed >> 11) / 9007199254740992.0 - 0.5;
  }
  const int m = std::min(kKrylov, n);
  Eigen::MatrixXd V(n, m + 1), H(m + 1, m);
  Eigen::VectorXd w(n);
  LargestMode out;
  for (int cycle = 0; cycle < kRestarts; ++cycle) {
    // (start x) => an Arnoldi factorisation J V_k = V_{k+1} H, Gram-Schmidt twice
    V.setZero();
    H.setZero();
    V.col(0) = x.normalized();
    int k = m;
    for (int j = 0; j < m; ++j) {
      apply(V.col(j), w);
      for (int pass = 0; pass < 2; ++pass) {
        const Eigen::VectorXd c = V.leftCols(j + 1).transpose() * w;
        w -= V.leftCols(j + 1) * c;
        H.col(j).head(j + 1) += c;
      }
      H(j + 1, j) = w.norm();
      if (H(j + 1, j) <= 1e-12 * H.col(j).head(j + 1).norm()) {  // an invariant subspace
        k = j + 1;
        break;
      }
      V.col(j + 1) = w / H(j + 1, j);
    }
    // (H_k) => the Ritz value of largest modulus, its vector and residual |h_{k+1,k} y_k|
    const Eigen::EigenSolver<Eigen::MatrixXd> eig(H.topLeftCorner(k, k), true);
    Eigen::Index top = 0;
    eig.eigenvalues().cwiseAbs().maxCoeff(&top);
    const Eigen::VectorXcd y = eig.eigenvectors().col(top).normalized();
    const Eigen::VectorXcd ritz = V.leftCols(k).cast<std::complex<double>>() * y;
    out.lambda = eig.eigenvalues()[top];
    out.shape = ritz.head(nv);
    out.residual = std::abs(H(k, k - 1) * y[k - 1]) / std::max(std::abs(out.lambda), 1e-300);
    if (k < m || out.residual <= kTol) break;
    // (not converged) => restart from the Ritz vector (its real and imaginary parts together)
    x = ritz.real() + ritz.imag();
  }
  return out;
}

}  // namespace yardsim::mechanics
