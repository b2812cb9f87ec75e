#include "dynamics/integrators/sparse_newton_matrix.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace yardsim::dynamics {

SparseNewtonMatrix::SparseNewtonMatrix(const Model& model, const JacobianPattern& pattern,
                                       const JacobianBlocks* blocks, bool band)
    : model_(model) {
  // (pattern) => A's compressed columns: the pattern's rows and the diagonal
  const int n = model.nv;
  if (pattern.n != n || static_cast<int>(pattern.rows.size()) != n)
    throw std::invalid_argument("SparseNewtonMatrix: the pattern is not nv x nv");
  std::vector<Eigen::Triplet<double>> entries;
  for (int j = 0; j < n; ++j) {
    entries.emplace_back(j, j, 1.0);
    for (int i : pattern.rows[static_cast<std::size_t>(j)]) entries.emplace_back(i, j, 1.0);
  }
  A_.resize(n, n);
  A_.setFromTriplets(entries.begin(), entries.end(), [](double a, double) { return a; });
  A_.makeCompressed();
  diagonal_.assign(static_cast<std::size_t>(n), -1);
  for (int j = 0; j < n; ++j)
    for (int k = A_.outerIndexPtr()[j]; k < A_.outerIndexPtr()[j + 1]; ++k)
      if (A_.innerIndexPtr()[k] == j) diagonal_[static_cast<std::size_t>(j)] = k;
  // (blocks) => their entries' places; the columns they cover whole leave the colouring
  auto place = [&](int i, int j) {
    for (int k = A_.outerIndexPtr()[j]; k < A_.outerIndexPtr()[j + 1]; ++k)
      if (A_.innerIndexPtr()[k] == i) return k;
    throw std::invalid_argument("SparseNewtonMatrix: a closed-form block lies outside the pattern");
  };
  std::vector<int> covered(static_cast<std::size_t>(n), 0);  // per column: rows in blocks
  if (blocks != nullptr) {
    for (const auto& [r0, c0] : blocks->at) {
      if (r0 < 0 || c0 < 0 || r0 + 3 > n || c0 + 3 > n)
        throw std::invalid_argument("SparseNewtonMatrix: a closed-form block leaves the matrix");
      std::array<int, 9> idx{};
      for (int b = 0; b < 3; ++b) {
        for (int a = 0; a < 3; ++a)
          idx[static_cast<std::size_t>(3 * b + a)] = place(r0 + a, c0 + b);
        covered[static_cast<std::size_t>(c0 + b)] += 3;
      }
      blockIndex_.push_back(idx);
    }
    // (3 x 1 blocks) => their entries' places, or -1 outside the pattern
    auto find = [&](int i, int j) {
      for (int k = A_.outerIndexPtr()[j]; k < A_.outerIndexPtr()[j + 1]; ++k)
        if (A_.innerIndexPtr()[k] == i) return k;
      return -1;
    };
    for (const auto& [r0, c0] : blocks->columns) {
      if (r0 < 0 || c0 < 0 || r0 + 3 > n || c0 >= n)
        throw std::invalid_argument("SparseNewtonMatrix: a closed-form block leaves the matrix");
      columnIndex_.push_back({find(r0, c0), find(r0 + 1, c0), find(r0 + 2, c0)});
    }
    dq_.assign(blockIndex_.size() + columnIndex_.size(), Eigen::Matrix3d::Zero());
    dv_.assign(blockIndex_.size() + columnIndex_.size(), Eigen::Matrix3d::Zero());
  }
  JacobianPattern differenced = pattern;  // the columns that still need differences
  std::vector<char> closed(static_cast<std::size_t>(n), 0);
  for (int j = 0; j < n; ++j) {
    auto& rows = differenced.rows[static_cast<std::size_t>(j)];
    const bool hasDiagonal = std::find(rows.begin(), rows.end(), j) != rows.end();
    const int count = static_cast<int>(rows.size());
    if (hasDiagonal && covered[static_cast<std::size_t>(j)] >= count) {
      closed[static_cast<std::size_t>(j)] = 1;
      rows.clear();
    }
  }
  colouring_ = colourColumns(differenced);
  if (blocks != nullptr) {
    // (colouring of all columns) => without the closed ones, empty colours dropped
    ColumnColouring kept;
    kept.colour.assign(static_cast<std::size_t>(n), -1);
    for (const auto& cols : colouring_.columns) {
      std::vector<int> open;
      for (int j : cols)
        if (!closed[static_cast<std::size_t>(j)]) open.push_back(j);
      if (open.empty()) continue;
      for (int j : open) kept.colour[static_cast<std::size_t>(j)] = kept.count();
      kept.columns.push_back(std::move(open));
    }
    colouring_ = std::move(kept);
  }
  fq_.setZero(A_.nonZeros());
  fv_.setZero(A_.nonZeros());
  fqm_.setZero(A_.nonZeros());
  for (Eigen::VectorXd* x : {&step_, &deltaP_, &vp_, &fp_}) x->setZero(n);
  qp_.setZero(model.nq);
  y_.setZero(n);
  work_.setZero(n);
  // (A a band matrix but for a few rows and columns, as lines on rigid bodies) => the band
  // solver, linear in the nodes; else SparseLU
  banded_ = band && band_.analyse(A_);
  if (!banded_) lu_.analyzePattern(A_);
}

void SparseNewtonMatrix::scatter(const std::vector<int>& cols, const Eigen::VectorXd& f,
                                 Eigen::VectorXd& values) {
  // (fp_ - f) / step in the rows of each column: no other column of the colour touches them
  for (int j : cols)
    for (int k = A_.outerIndexPtr()[j]; k < A_.outerIndexPtr()[j + 1]; ++k) {
      const int i = A_.innerIndexPtr()[k];
      values[k] = (fp_[i] - f[i]) / step_[j];
    }
}

bool SparseNewtonMatrix::applyBlocks(std::uint64_t signature) {
  // (blocks) => their nine entries each in F_q and F_v
  for (std::size_t b = 0; b < blockIndex_.size(); ++b)
    for (int e = 0; e < 9; ++e) {
      const auto k = static_cast<std::size_t>(e);
      fq_[blockIndex_[b][k]] = dq_[b](e % 3, e / 3);
      fv_[blockIndex_[b][k]] = dv_[b](e % 3, e / 3);
    }
  for (std::size_t c = 0; c < columnIndex_.size(); ++c) {
    const std::size_t b = blockIndex_.size() + c;
    for (int e = 0; e < 3; ++e) {
      const int k = columnIndex_[c][static_cast<std::size_t>(e)];
      if (k < 0) continue;
      fq_[k] = dq_[b](e, 0);
      fv_[k] = dv_[b](e, 0);
    }
  }
  const bool changed = !applied_ || signature != signature_;
  applied_ = true;
  signature_ = signature;
  return changed;
}

bool SparseNewtonMatrix::factorise(double cq, double cv) {
  // (F_q, F_v on the structure) => A's values, then the numeric LU on the analysed ordering
  Eigen::Map<Eigen::VectorXd> a(A_.valuePtr(), A_.nonZeros());
  a = -cq * fq_ - cv * fv_;
  for (int k : diagonal_) a[k] += 1.0;
  return factoriseValues();
}

bool SparseNewtonMatrix::groupColumns(int first, int k) {
  // (columns first .. first + k - 1) => kept when their row lists in A are equal
  if (first < 0 || k < 1 || k > 6 || first + k > A_.cols()) return false;
  const int* outer = A_.outerIndexPtr();
  const int count = outer[first + 1] - outer[first];
  for (int c = first + 1; c < first + k; ++c) {
    if (outer[c + 1] - outer[c] != count) return false;
    for (int e = 0; e < count; ++e)
      if (A_.innerIndexPtr()[outer[c] + e] != A_.innerIndexPtr()[outer[first] + e]) return false;
  }
  groups_.push_back({first, k});
  return true;
}

bool SparseNewtonMatrix::factorise(double cq, double cv,
                                   const std::vector<Eigen::Matrix<double, 6, 6>>& maps) {
  // (F_q, maps) => F_q M: in each group's rows, the row of its k columns times M_g
  fqm_ = fq_;
  const int* outer = A_.outerIndexPtr();
  for (std::size_t g = 0; g < groups_.size() && g < maps.size(); ++g) {
    const auto [first, k] = groups_[g];
    const int count = outer[first + 1] - outer[first];
    for (int e = 0; e < count; ++e)
      for (int b = 0; b < k; ++b) {
        double sum = 0.0;
        for (int c = 0; c < k; ++c) sum += fq_[outer[first + c] + e] * maps[g](c, b);
        fqm_[outer[first + b] + e] = sum;
      }
  }
  // (F_q M, F_v) => A's values, its LU
  Eigen::Map<Eigen::VectorXd> a(A_.valuePtr(), A_.nonZeros());
  a = -cq * fqm_ - cv * fv_;
  for (int k : diagonal_) a[k] += 1.0;
  return factoriseValues();
}

void SparseNewtonMatrix::addFq(double c, const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  // (F_q on A's compressed columns) => y += c F_q x, column by column
  for (Eigen::Index j = 0; j < A_.cols(); ++j) {
    const double cx = c * x[j];
    if (cx == 0.0) continue;
    for (int k = A_.outerIndexPtr()[j]; k < A_.outerIndexPtr()[j + 1]; ++k)
      y[A_.innerIndexPtr()[k]] += cx * fq_[k];
  }
}

bool SparseNewtonMatrix::factoriseValues() {
  if (banded_) {
    ok_ = band_.factorise(A_);
    return ok_;
  }
  lu_.refactorize(A_);
  ok_ = lu_.info() == Eigen::Success;
  return ok_;
}

namespace {
// (L of a SparseLU: unit lower, supernodal; x; work sized n, zero) => x = L^-1 x. Eigen 3.4's
// MappedSuperNodalMatrix::solveInPlace with its work vector passed in instead of allocated
template <class Supernodal>
void lowerSolve(const Supernodal& L, Eigen::VectorXd& x, Eigen::VectorXd& work) {
  using Map = Eigen::Map<const Eigen::MatrixXd, 0, Eigen::OuterStride<>>;
  const double* values = L.valuePtr();
  for (Eigen::Index k = 0; k <= L.nsuper(); ++k) {
    const Eigen::Index first = L.supToCol()[k], start = L.rowIndexPtr()[first];
    const Eigen::Index rows = L.rowIndexPtr()[first + 1] - start;
    const Eigen::Index cols = L.supToCol()[k + 1] - first, below = rows - cols;
    if (cols == 1) {
      typename Supernodal::InnerIterator it(L, first);
      for (++it; it; ++it) x[it.row()] -= x[first] * it.value();
      continue;
    }
    const Eigen::Index at = L.colIndexPtr()[first];
    const Eigen::Index lda = L.colIndexPtr()[first + 1] - at;
    auto u = x.segment(first, cols);
    Map(values + at, cols, cols, Eigen::OuterStride<>(lda))
        .triangularView<Eigen::UnitLower>()
        .solveInPlace(u);
    work.head(below).noalias() =
        Map(values + at + cols, below, cols, Eigen::OuterStride<>(lda)) * u;
    for (Eigen::Index i = 0; i < below; ++i) {
      x[L.rowIndex()[start + cols + i]] -= work[i];
      work[i] = 0.0;
    }
  }
}
}  // namespace

void SparseNewtonMatrix::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  // (b) => P_c^-1 U^-1 L^-1 P_r b, as SparseLU::solve but in the preallocated y_, work_ and x
  if (!ok_) {
    x.setConstant(std::numeric_limits<double>::quiet_NaN());
    return;
  }
  if (banded_) {
    band_.solve(b, x);
    return;
  }
  const auto& pr = lu_.rowsPermutation().indices();
  const auto& pc = lu_.colsPermutation().indices();
  for (Eigen::Index i = 0; i < b.size(); ++i) y_[pr[i]] = b[i];
  lowerSolve(lu_.matrixL().m_mapL, y_, work_);
  lu_.matrixU().solveInPlace(y_);
  x.resize(b.size());
  for (Eigen::Index i = 0; i < b.size(); ++i) x[i] = y_[pc[i]];
}

void SparseNewtonMatrix::solve(const Eigen::MatrixXd& B, Eigen::MatrixXd& X) const {
  if (!ok_) {
    X.setConstant(std::numeric_limits<double>::quiet_NaN());
    return;
  }
  if (banded_) {
    X.resize(B.rows(), B.cols());
    for (Eigen::Index c = 0; c < B.cols(); ++c) {
      y_ = B.col(c);
      band_.solve(y_, work_);
      X.col(c) = work_;
    }
    return;
  }
  X = lu_.solve(B);
}

Eigen::MatrixXd SparseNewtonMatrix::denseFq() const {
  Eigen::SparseMatrix<double> m = A_;
  Eigen::Map<Eigen::VectorXd>(m.valuePtr(), m.nonZeros()) = fq_;
  return Eigen::MatrixXd(m);
}

Eigen::MatrixXd SparseNewtonMatrix::denseFv() const {
  Eigen::SparseMatrix<double> m = A_;
  Eigen::Map<Eigen::VectorXd>(m.valuePtr(), m.nonZeros()) = fv_;
  return Eigen::MatrixXd(m);
}

}  // namespace yardsim::dynamics
