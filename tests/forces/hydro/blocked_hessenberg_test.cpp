// The blocked Hessenberg reduction behind the free surface's growth check: the reduced matrix is
// upper Hessenberg and orthogonally similar to the original (trace, Frobenius norm, eigenvalues),
// against Eigen's unblocked EigenSolver on random matrices of several sizes and panel widths, on
// a matrix whose columns are already reduced (reflectors of zero length), and on one with known
// complex eigenvalues.
#include <catch2/catch.hpp>

#include <algorithm>
#include <complex>
#include <vector>

#include <Eigen/Eigenvalues>

#include "forces/hydro/blocked_hessenberg.hpp"

using namespace yardsim::forces::hydro;

namespace {

// (eigenvalues) => sorted by real part, then imaginary part
std::vector<std::complex<double>> sorted(const Eigen::VectorXcd& e) {
  std::vector<std::complex<double>> v(e.data(), e.data() + e.size());
  std::sort(v.begin(), v.end(), [](auto a, auto b) {
    return a.real() != b.real() ? a.real() < b.real() : a.imag() < b.imag();
  });
  return v;
}

// (two spectra of the same size, scale) => the largest distance of one's eigenvalues from the
// nearest of the other's (each matched once, greedily), over the scale
double spectrumDistance(const Eigen::VectorXcd& a, const Eigen::VectorXcd& b, double scale) {
  std::vector<std::complex<double>> left = sorted(a), right = sorted(b);
  double worst = 0.0;
  for (const auto& x : left) {
    auto best = right.begin();
    for (auto it = right.begin(); it != right.end(); ++it)
      if (std::abs(*it - x) < std::abs(*best - x)) best = it;
    worst = std::max(worst, std::abs(*best - x));
    right.erase(best);
  }
  return worst / scale;
}

}  // namespace

TEST_CASE("the blocked reduction is upper Hessenberg and orthogonally similar to the matrix") {
  for (const int n : {3, 7, 40, 131}) {
    for (const int panel : {1, 5, 32}) {
      std::srand(static_cast<unsigned>(n * 100 + panel));
      const Eigen::MatrixXd A = Eigen::MatrixXd::Random(n, n);
      Eigen::MatrixXd H = A;
      reduceToHessenberg(H, panel);
      INFO("n " << n << " panel " << panel);
      for (int c = 0; c < n; ++c)
        for (int r = c + 2; r < n; ++r) CHECK(H(r, c) == 0.0);
      CHECK(H.trace() == Approx(A.trace()).margin(1e-12 * n));
      CHECK(H.norm() == Approx(A.norm()).epsilon(1e-13));
      // (orthogonal similarity) => the same characteristic polynomial: the same eigenvalues
      const Eigen::VectorXcd reference =
          Eigen::EigenSolver<Eigen::MatrixXd>(A, false).eigenvalues();
      CHECK(spectrumDistance(eigenvaluesByBlockedHessenberg(A), reference, A.norm()) < 1e-11);
      // (A H^k) => the same traces of powers: tr(A^2), tr(A^3)
      CHECK((H * H).trace() == Approx((A * A).trace()).margin(1e-11 * A.squaredNorm()));
    }
  }
}

TEST_CASE("columns already reduced give reflectors of zero length and are kept") {
  // (an upper Hessenberg matrix) => itself: every reflector is the identity
  std::srand(7);
  Eigen::MatrixXd A = Eigen::MatrixXd::Random(50, 50);
  for (int c = 0; c < 50; ++c)
    for (int r = c + 2; r < 50; ++r) A(r, c) = 0.0;
  Eigen::MatrixXd H = A;
  reduceToHessenberg(H, 8);
  CHECK((H - A).norm() == 0.0);
}

TEST_CASE("a block-diagonal matrix of rotations has its complex pairs back") {
  // (2 x 2 blocks [a -b; b a]) => a +- i b, hidden by an orthogonal similarity
  const int m = 30;
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(2 * m, 2 * m);
  Eigen::VectorXcd expected(2 * m);
  for (int k = 0; k < m; ++k) {
    const double a = 0.1 * k - 1.0, b = 0.5 + 0.03 * k;
    D.block<2, 2>(2 * k, 2 * k) << a, -b, b, a;
    expected(2 * k) = {a, b};
    expected(2 * k + 1) = {a, -b};
  }
  std::srand(11);
  const Eigen::MatrixXd Q =
      Eigen::HouseholderQR<Eigen::MatrixXd>(Eigen::MatrixXd::Random(2 * m, 2 * m)).householderQ();
  const Eigen::MatrixXd A = Q * D * Q.transpose();
  CHECK(spectrumDistance(eigenvaluesByBlockedHessenberg(A), expected, 1.0) < 1e-12);
}
