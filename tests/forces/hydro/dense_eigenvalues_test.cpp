// LAPACK's eigenvalues behind the free surface's growth check: against Eigen's EigenSolver on
// random matrices of several sizes, on spectra known in closed form hidden by an orthogonal
// similarity (complex pairs, a real spectrum), through the invariants of the characteristic
// polynomial (trace, determinant), and the refusals.
#include <catch2/catch.hpp>

#include <algorithm>
#include <complex>
#include <limits>
#include <stdexcept>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/QR>

#include "forces/hydro/dense_eigenvalues.hpp"

using namespace yardsim::forces::hydro;

namespace {

// (two spectra of the same size, scale) => the largest distance of one's eigenvalues from the
// nearest of the other's (each matched once, greedily), over the scale
double spectrumDistance(const Eigen::VectorXcd& a, const Eigen::VectorXcd& b, double scale) {
  REQUIRE(a.size() == b.size());
  std::vector<std::complex<double>> right(b.data(), b.data() + b.size());
  double worst = 0.0;
  for (Eigen::Index k = 0; k < a.size(); ++k) {
    auto best = right.begin();
    for (auto it = right.begin(); it != right.end(); ++it)
      if (std::abs(*it - a(k)) < std::abs(*best - a(k))) best = it;
    worst = std::max(worst, std::abs(*best - a(k)));
    right.erase(best);
  }
  return worst / scale;
}

// (n, seed) => an orthogonal n x n matrix
Eigen::MatrixXd orthogonal(int n, unsigned seed) {
  std::srand(seed);
  return Eigen::HouseholderQR<Eigen::MatrixXd>(Eigen::MatrixXd::Random(n, n)).householderQ();
}

}  // namespace

TEST_CASE("LAPACK's eigenvalues are Eigen's on random matrices") {
  for (const int n : {1, 2, 3, 7, 40, 131, 300}) {
    std::srand(static_cast<unsigned>(n));
    const Eigen::MatrixXd A = Eigen::MatrixXd::Random(n, n);
    const Eigen::VectorXcd e = denseEigenvalues(A);
    INFO("n " << n);
    const Eigen::VectorXcd reference = Eigen::EigenSolver<Eigen::MatrixXd>(A, false).eigenvalues();
    CHECK(spectrumDistance(e, reference, A.norm()) < 1e-11);
    // (characteristic polynomial) => sum of the eigenvalues = trace, product = determinant
    CHECK(e.sum().real() == Approx(A.trace()).margin(1e-12 * n * A.norm()));
    CHECK(std::abs(e.sum().imag()) < 1e-12 * n * A.norm());
    CHECK(e.prod().real() == Approx(A.determinant()).epsilon(1e-9).margin(1e-300));
  }
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
  const Eigen::MatrixXd Q = orthogonal(2 * m, 11);
  const Eigen::VectorXcd e = denseEigenvalues(Q * D * Q.transpose());
  CHECK(spectrumDistance(e, expected, 1.0) < 1e-12);
  // (LAPACK's order) => each pair next to each other, the positive imaginary part first
  for (int k = 0; k + 1 < 2 * m; k += 2) {
    CHECK(e(k).imag() > 0.0);
    CHECK(e(k + 1) == std::conj(e(k)));
  }
}

TEST_CASE("a real spectrum spread over eight decades stays real and exact to its size") {
  // (diag(10^(-4 + 8 k / (n - 1))) under an orthogonal similarity) => the same, relative to the
  // largest; no imaginary parts beyond round-off
  const int n = 80;
  Eigen::VectorXd d(n);
  for (int k = 0; k < n; ++k) d(k) = std::pow(10.0, -4.0 + 8.0 * k / (n - 1));
  const Eigen::MatrixXd Q = orthogonal(n, 5);
  const Eigen::VectorXcd e = denseEigenvalues(Q * d.asDiagonal() * Q.transpose());
  CHECK(spectrumDistance(e, d.cast<std::complex<double>>(), d.maxCoeff()) < 1e-13);
  CHECK(e.imag().cwiseAbs().maxCoeff() < 1e-12 * d.maxCoeff());
}

TEST_CASE("a matrix that is not square is refused, an empty one has no eigenvalues") {
  CHECK_THROWS_AS(denseEigenvalues(Eigen::MatrixXd::Zero(3, 4)), std::invalid_argument);
  CHECK(denseEigenvalues(Eigen::MatrixXd(0, 0)).size() == 0);
  // (a NaN or an infinity) => refused before LAPACK sees it
  Eigen::MatrixXd A = Eigen::MatrixXd::Identity(4, 4);
  A(2, 1) = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(denseEigenvalues(A), std::invalid_argument);
  A(2, 1) = -std::numeric_limits<double>::infinity();
  CHECK_THROWS_AS(denseEigenvalues(A), std::invalid_argument);
}
