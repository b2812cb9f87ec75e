#include "forces/hydro/blocked_hessenberg.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Eigenvalues>

namespace yardsim::forces::hydro {

void reduceToHessenberg(Eigen::MatrixXd& A, int panel) {
  const Eigen::Index n = A.rows();
  if (A.cols() != n) throw std::invalid_argument("reduceToHessenberg: the matrix is not square");
  const Eigen::Index nb = std::max(1, panel);
  Eigen::MatrixXd V(n, nb), Y(n, nb), T(nb, nb);
  Eigen::VectorXd w(nb), z(nb);
  // (columns k .. k + b - 1) => their reflectors H_j = I - tau v v^T (v zero above row j + 1,
  // 1 there), gathered as P = H_k ... H_k+b-1 = I - V T V^T and Y = A V T with A as at the panel's
  // start; then the trailing columns: A <- P^T (A - Y V^T)
  for (Eigen::Index k = 0; k + 2 < n; k += nb) {
    const Eigen::Index b = std::min(nb, n - 2 - k);
    V.setZero();
    T.setZero();
    for (Eigen::Index i = 0; i < b; ++i) {
      const Eigen::Index j = k + i, m = n - j - 1;  // (column j) => rows j + 1 .. n - 1
      auto a = A.col(j);
      if (i > 0) {
        // (the panel's earlier reflectors) => column j of P^T (A - Y V^T): right, then left
        a.noalias() -= Y.leftCols(i) * V.row(j).head(i).transpose();
        auto wi = w.head(i);
        wi.noalias() = V.block(k + 1, 0, n - k - 1, i).transpose() * a.tail(n - k - 1);
        z.head(i).noalias() = T.topLeftCorner(i, i).transpose().triangularView<Eigen::Lower>() * wi;
        a.tail(n - k - 1).noalias() -= V.block(k + 1, 0, n - k - 1, i) * z.head(i);
      }
      // (a(j + 1 ..)) => v, tau, beta: a(j + 1) = beta, below it 0
      const double alpha = a(j + 1);
      const double sigma = m > 1 ? a.tail(m - 1).squaredNorm() : 0.0;
      double tau = 0.0;
      V(j + 1, i) = 1.0;
      if (sigma > 0.0) {
        const double beta = alpha >= 0.0 ? -std::sqrt(alpha * alpha + sigma)
                                         : std::sqrt(alpha * alpha + sigma);
        tau = (beta - alpha) / beta;
        V.col(i).tail(m - 1) = a.tail(m - 1) / (alpha - beta);
        a(j + 1) = beta;
        a.tail(m - 1).setZero();
      }
      // (v, tau) => T's column i, Y's column i = tau (A v - Y (V^T v)) with A as at the start
      auto vi = V.col(i).tail(m);
      auto yi = Y.col(i);
      yi.noalias() = A.rightCols(m) * vi;
      if (i > 0) {
        auto wi = w.head(i);
        wi.noalias() = V.block(j + 1, 0, m, i).transpose() * vi;
        yi.noalias() -= Y.leftCols(i) * wi;
        z.head(i).noalias() = T.topLeftCorner(i, i).triangularView<Eigen::Upper>() * wi;
        T.col(i).head(i) = -tau * z.head(i);
      }
      yi *= tau;
      T(i, i) = tau;
    }
    // (V, T, Y) => the columns after the panel: right A -= Y V^T, left A <- (I - V T^T V^T) A
    const Eigen::Index c = k + b, rest = n - c;
    if (rest == 0) continue;
    auto Vp = V.leftCols(b);
    auto right = A.rightCols(rest);
    right.noalias() -= Y.leftCols(b) * Vp.bottomRows(rest).transpose();
    auto lower = A.block(k + 1, c, n - k - 1, rest);
    Eigen::MatrixXd W = Vp.bottomRows(n - k - 1).transpose() * lower;
    W = T.topLeftCorner(b, b).transpose().triangularView<Eigen::Lower>() * W;
    lower.noalias() -= Vp.bottomRows(n - k - 1) * W;
  }
}

Eigen::VectorXcd eigenvaluesByBlockedHessenberg(Eigen::MatrixXd A) {
  reduceToHessenberg(A);
  const Eigen::Index n = A.rows();
  const Eigen::MatrixXd Q = Eigen::MatrixXd::Identity(n, n);  // (not used: computeU false)
  Eigen::RealSchur<Eigen::MatrixXd> schur(n);
  schur.computeFromHessenberg(A, Q, false);
  if (schur.info() != Eigen::Success)
    throw std::runtime_error("eigenvalues: the QR iteration did not converge");
  // (the quasi-triangular T) => 1 x 1 blocks real eigenvalues, 2 x 2 blocks complex pairs
  const Eigen::MatrixXd& S = schur.matrixT();
  Eigen::VectorXcd out(n);
  for (Eigen::Index i = 0; i < n;) {
    if (i + 1 < n && S(i + 1, i) != 0.0) {
      const double p = 0.5 * (S(i, i) - S(i + 1, i + 1));
      const double q = p * p + S(i + 1, i) * S(i, i + 1);  // < 0 for a standardised complex pair
      const double re = S(i + 1, i + 1) + p, im = std::sqrt(std::abs(q));
      out(i) = {re, im};
      out(i + 1) = {re, -im};
      i += 2;
    } else {
      out(i) = S(i, i);
      ++i;
    }
  }
  return out;
}

}  // namespace yardsim::forces::hydro
