#include "forces/hydro/blocked_hessenberg.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

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
        const double beta =
            alpha >= 0.0 ? -std::sqrt(alpha * alpha + sigma) : std::sqrt(alpha * alpha + sigma);
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

namespace {

// (upper Hessenberg H, overwritten) => its eigenvalues by the Francis double-shift QR iteration on
// the active window only (the eigenvalues alone: rows and columns outside the window that a Schur
// form would also update are left as they are), deflating at negligible subdiagonals; the
// classic EISPACK hqr (Wilkinson and Reinsch, "Handbook for Automatic Computation II", II/14)
Eigen::VectorXcd hessenbergEigenvalues(Eigen::MatrixXd& a) {
  const Eigen::Index n = a.rows();
  Eigen::VectorXcd out(n);
  double norm = 0.0;  // (the Hessenberg part's entries) => the scale of a negligible subdiagonal
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index i = 0; i <= std::min(j + 1, n - 1); ++i) norm += std::abs(a(i, j));
  double shift = 0.0;  // (exceptional shifts) => the sum taken out of the diagonal
  int its = 0;
  for (Eigen::Index nn = n - 1; nn >= 0;) {
    // (window's end nn) => its start l: the last negligible subdiagonal above nn
    Eigen::Index l = nn;
    for (; l >= 1; --l) {
      double s = std::abs(a(l - 1, l - 1)) + std::abs(a(l, l));
      if (s == 0.0) s = norm;
      if (std::abs(a(l, l - 1)) + s == s) {
        a(l, l - 1) = 0.0;
        break;
      }
    }
    double x = a(nn, nn);
    if (l == nn) {  // (1 x 1 block) => a real eigenvalue
      out(nn) = x + shift;
      --nn;
      its = 0;
      continue;
    }
    double y = a(nn - 1, nn - 1), w = a(nn, nn - 1) * a(nn - 1, nn);
    if (l == nn - 1) {  // (2 x 2 block) => a real pair or a complex pair
      const double p = 0.5 * (y - x), q = p * p + w;
      double z = std::sqrt(std::abs(q));
      x += shift;
      if (q >= 0.0) {
        z = p + (p >= 0.0 ? z : -z);
        out(nn - 1) = x + z;
        out(nn) = z != 0.0 ? x - w / z : x + z;
      } else {
        out(nn - 1) = {x + p, z};
        out(nn) = {x + p, -z};
      }
      nn -= 2;
      its = 0;
      continue;
    }
    if (its == 60) throw std::runtime_error("eigenvalues: the QR iteration did not converge");
    if (its == 10 || its == 20 || its == 40) {  // (slow convergence) => an exceptional shift
      shift += x;
      for (Eigen::Index i = 0; i <= nn; ++i) a(i, i) -= x;
      const double s = std::abs(a(nn, nn - 1)) + std::abs(a(nn - 1, nn - 2));
      x = y = 0.75 * s;
      w = -0.4375 * s * s;
    }
    ++its;
    // (shifts from the trailing 2 x 2: x, y, w) => the first column of the double-shift
    // polynomial, started at m where two consecutive small subdiagonals allow it
    Eigen::Index m = nn - 2;
    double p = 0.0, q = 0.0, r = 0.0;
    for (;; --m) {
      const double z = a(m, m), rr = x - z, ss = y - z;
      p = (rr * ss - w) / a(m + 1, m) + a(m, m + 1);
      q = a(m + 1, m + 1) - z - rr - ss;
      r = a(m + 2, m + 1);
      const double s = std::abs(p) + std::abs(q) + std::abs(r);
      p /= s;
      q /= s;
      r /= s;
      if (m == l) break;
      const double u = std::abs(a(m, m - 1)) * (std::abs(q) + std::abs(r));
      const double v =
          std::abs(p) * (std::abs(a(m - 1, m - 1)) + std::abs(z) + std::abs(a(m + 1, m + 1)));
      if (u + v == v) break;
    }
    for (Eigen::Index i = m + 2; i <= nn; ++i) {
      a(i, i - 2) = 0.0;
      if (i != m + 2) a(i, i - 3) = 0.0;
    }
    // (bulge) => chased down the window by 3 x 3 reflectors, applied within the window
    for (Eigen::Index k = m; k <= nn - 1; ++k) {
      if (k != m) {
        p = a(k, k - 1);
        q = a(k + 1, k - 1);
        r = k != nn - 1 ? a(k + 2, k - 1) : 0.0;
        x = std::abs(p) + std::abs(q) + std::abs(r);
        if (x != 0.0) {
          p /= x;
          q /= x;
          r /= x;
        }
      }
      const double norm3 = std::sqrt(p * p + q * q + r * r);
      const double s = p >= 0.0 ? norm3 : -norm3;
      if (s == 0.0) continue;
      if (k == m) {
        if (l != m) a(k, k - 1) = -a(k, k - 1);
      } else {
        a(k, k - 1) = -s * x;
      }
      p += s;
      x = p / s;
      y = q / s;
      const double z = r / s;
      q /= p;
      r /= p;
      for (Eigen::Index j = k; j <= nn; ++j) {  // (rows k .. k + 2) => from the left
        double t = a(k, j) + q * a(k + 1, j);
        if (k != nn - 1) {
          t += r * a(k + 2, j);
          a(k + 2, j) -= t * z;
        }
        a(k + 1, j) -= t * y;
        a(k, j) -= t * x;
      }
      const Eigen::Index last = std::min(nn, k + 3);
      for (Eigen::Index i = l; i <= last; ++i) {  // (columns k .. k + 2) => from the right
        double t = x * a(i, k) + y * a(i, k + 1);
        if (k != nn - 1) {
          t += z * a(i, k + 2);
          a(i, k + 2) -= t * r;
        }
        a(i, k + 1) -= t * q;
        a(i, k) -= t;
      }
    }
  }
  return out;
}

}  // namespace

Eigen::VectorXcd eigenvaluesByBlockedHessenberg(Eigen::MatrixXd A) {
  reduceToHessenberg(A);
  return hessenbergEigenvalues(A);
}

}  // namespace yardsim::forces::hydro
