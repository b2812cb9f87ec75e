#include "dynamics/integrators/bordered_band_lu.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace yardsim::dynamics {

bool BorderedBandLu::analyse(const Eigen::SparseMatrix<double>& A, int maxBand, int maxBorder) {
  n_ = ni_ = r_ = w_ = 0;
  if (A.rows() != A.cols() || A.rows() == 0 || !A.isCompressed()) return false;
  const int n = static_cast<int>(A.rows());
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  // (entries farther than maxBand from the diagonal) => per dof their count; the border taken
  // greedily, the dof with most of them first, until none is left
  std::vector<int> far(static_cast<std::size_t>(n), 0);
  std::vector<char> inBorder(static_cast<std::size_t>(n), 0);
  for (int j = 0; j < n; ++j)
    for (int k = outer[j]; k < outer[j + 1]; ++k)
      if (std::abs(inner[k] - j) > maxBand) {
        ++far[static_cast<std::size_t>(inner[k])];
        ++far[static_cast<std::size_t>(j)];
      }
  border_.clear();
  for (;;) {
    const auto most = std::max_element(far.begin(), far.end());
    if (*most == 0) break;
    const int d = static_cast<int>(most - far.begin());
    if (static_cast<int>(border_.size()) == maxBorder) return false;
    border_.push_back(d);
    inBorder[static_cast<std::size_t>(d)] = 1;
    // (d set aside) => its far entries no longer count for the dofs they join it to
    for (int j = 0; j < n; ++j)
      for (int k = outer[j]; k < outer[j + 1]; ++k) {
        const int i = inner[k];
        if ((i == d) == (j == d) || std::abs(i - j) <= maxBand) continue;
        const int other = i == d ? j : i;
        if (!inBorder[static_cast<std::size_t>(other)]) --far[static_cast<std::size_t>(other)];
      }
    far[static_cast<std::size_t>(d)] = 0;
  }
  std::sort(border_.begin(), border_.end());
  // (interior in A's order) => new indices; the band's half-width among them
  std::vector<int> index(static_cast<std::size_t>(n), -1);
  interior_.clear();
  for (int d = 0; d < n; ++d)
    if (!inBorder[static_cast<std::size_t>(d)]) {
      index[static_cast<std::size_t>(d)] = static_cast<int>(interior_.size());
      interior_.push_back(d);
    }
  for (std::size_t b = 0; b < border_.size(); ++b)
    index[static_cast<std::size_t>(border_[b])] = static_cast<int>(b);
  n_ = n;
  ni_ = static_cast<int>(interior_.size());
  r_ = static_cast<int>(border_.size());
  for (int j = 0; j < n; ++j)
    for (int k = outer[j]; k < outer[j + 1]; ++k) {
      const int i = inner[k];
      if (!inBorder[static_cast<std::size_t>(i)] && !inBorder[static_cast<std::size_t>(j)])
        w_ = std::max(
            w_, std::abs(index[static_cast<std::size_t>(i)] - index[static_cast<std::size_t>(j)]));
    }
  // (entries) => their stores: the band (LAPACK's AB with kl = ku = w, fill to 2w above), C, D, E
  kv_ = 2 * w_;
  ld_ = static_cast<std::size_t>(3 * w_ + 1);
  kind_.assign(static_cast<std::size_t>(A.nonZeros()), 0);
  at_.assign(static_cast<std::size_t>(A.nonZeros()), 0);
  for (int j = 0; j < n; ++j)
    for (int k = outer[j]; k < outer[j + 1]; ++k) {
      const int i = inner[k];
      const auto ki = static_cast<std::size_t>(k);
      const int ni = index[static_cast<std::size_t>(i)], nj = index[static_cast<std::size_t>(j)];
      const bool bi = inBorder[static_cast<std::size_t>(i)],
                 bj = inBorder[static_cast<std::size_t>(j)];
      if (!bi && !bj) {
        kind_[ki] = 0;
        at_[ki] = static_cast<std::size_t>(nj) * ld_ + static_cast<std::size_t>(kv_ + ni - nj);
      } else if (!bi) {  // C: interior row, border column
        kind_[ki] = 1;
        at_[ki] = static_cast<std::size_t>(nj) * static_cast<std::size_t>(ni_) +
                  static_cast<std::size_t>(ni);
      } else if (!bj) {  // D: border row, interior column
        kind_[ki] = 2;
        at_[ki] = static_cast<std::size_t>(nj) * static_cast<std::size_t>(r_) +
                  static_cast<std::size_t>(ni);
      } else {
        kind_[ki] = 3;
        at_[ki] = static_cast<std::size_t>(nj) * static_cast<std::size_t>(r_) +
                  static_cast<std::size_t>(ni);
      }
    }
  ab_.assign(ld_ * static_cast<std::size_t>(ni_), 0.0);
  pivot_.assign(static_cast<std::size_t>(ni_), 0);
  C_.setZero(ni_, r_);
  D_.setZero(r_, ni_);
  E_.setZero(r_, r_);
  luS_ = Eigen::PartialPivLU<Eigen::MatrixXd>(r_);
  yi_.setZero(ni_);
  yb_.setZero(r_);
  s_.setZero(r_);
  return true;
}

bool BorderedBandLu::factorise(const Eigen::SparseMatrix<double>& A) {
  // (A's values) => the band, C, D and E
  std::fill(ab_.begin(), ab_.end(), 0.0);
  C_.setZero();
  D_.setZero();
  E_.setZero();
  const double* values = A.valuePtr();
  for (std::size_t k = 0; k < kind_.size(); ++k) {
    double* store = kind_[k] == 0   ? ab_.data()
                    : kind_[k] == 1 ? C_.data()
                    : kind_[k] == 2 ? D_.data()
                                    : E_.data();
    store[at_[k]] = values[k];
  }
  // (band) => L and U in place with row interchanges (dgbtf2): column j's pivot among its w
  // subdiagonal rows, the swap over the columns the band reaches, the rank-1 update
  int ju = 0;
  for (int j = 0; j < ni_; ++j) {
    const int km = std::min(w_, ni_ - 1 - j);
    int jp = 0;
    for (int i = 1; i <= km; ++i)
      if (std::abs(band(j + i, j)) > std::abs(band(j + jp, j))) jp = i;
    pivot_[static_cast<std::size_t>(j)] = j + jp;
    if (band(j + jp, j) == 0.0) return false;
    ju = std::max(ju, std::min(j + w_ + jp, ni_ - 1));
    if (jp != 0)
      for (int c = j; c <= ju; ++c) std::swap(band(j, c), band(j + jp, c));
    const double inv = 1.0 / band(j, j);
    for (int i = 1; i <= km; ++i) band(j + i, j) *= inv;
    for (int c = j + 1; c <= ju; ++c) {
      const double u = band(j, c);
      if (u == 0.0) continue;
      for (int i = 1; i <= km; ++i) band(j + i, c) -= band(j + i, j) * u;
    }
  }
  // (border) => X = B^-1 C in C's place, S = E - D X in E's place, its LU
  for (int b = 0; b < r_; ++b) bandSolve(C_.col(b).data());
  if (r_ > 0) {
    E_.noalias() -= D_ * C_;
    luS_.compute(E_);
    for (int b = 0; b < r_; ++b)
      if (!std::isfinite(luS_.matrixLU()(b, b)) || luS_.matrixLU()(b, b) == 0.0) return false;
  }
  return true;
}

void BorderedBandLu::bandSolve(double* y) const {
  // (y) => L^-1 y with the interchanges, then U^-1 y (U's band 2w above the diagonal)
  for (int j = 0; j + 1 < ni_; ++j) {
    const int p = pivot_[static_cast<std::size_t>(j)];
    if (p != j) std::swap(y[j], y[p]);
    const int km = std::min(w_, ni_ - 1 - j);
    for (int i = 1; i <= km; ++i) y[j + i] -= band(j + i, j) * y[j];
  }
  for (int j = ni_ - 1; j >= 0; --j) {
    y[j] /= band(j, j);
    for (int i = std::max(0, j - kv_); i < j; ++i) y[i] -= band(i, j) * y[j];
  }
}

void BorderedBandLu::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  // (b) => y = B^-1 b_i; s = S^-1 (b_b - D y); x_i = y - X s
  for (int i = 0; i < ni_; ++i) yi_[i] = b[interior_[static_cast<std::size_t>(i)]];
  bandSolve(yi_.data());
  if (r_ > 0) {
    for (int k = 0; k < r_; ++k) yb_[k] = b[border_[static_cast<std::size_t>(k)]];
    yb_.noalias() -= D_ * yi_;
    s_ = luS_.solve(yb_);
    yi_.noalias() -= C_ * s_;
  }
  x.resize(n_);
  for (int i = 0; i < ni_; ++i) x[interior_[static_cast<std::size_t>(i)]] = yi_[i];
  for (int k = 0; k < r_; ++k) x[border_[static_cast<std::size_t>(k)]] = s_[k];
}

}  // namespace yardsim::dynamics
