#include "dynamics/integrators/sparse_newton_matrix.hpp"

#include <limits>
#include <stdexcept>

namespace yardsim::dynamics {

SparseNewtonMatrix::SparseNewtonMatrix(const Model& model, const JacobianPattern& pattern)
    : model_(model) {
  // (pattern) => colouring; A's compressed columns: the pattern's rows and the diagonal
  const int n = model.nv;
  if (pattern.n != n || static_cast<int>(pattern.rows.size()) != n)
    throw std::invalid_argument("SparseNewtonMatrix: the pattern is not nv x nv");
  colouring_ = colourColumns(pattern);
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
  fq_.setZero(A_.nonZeros());
  fv_.setZero(A_.nonZeros());
  for (Eigen::VectorXd* x : {&step_, &deltaP_, &vp_, &fp_}) x->setZero(n);
  qp_.setZero(model.nq);
  lu_.analyzePattern(A_);
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

bool SparseNewtonMatrix::factorise(double cq, double cv) {
  // (F_q, F_v on the structure) => A's values, then the numeric LU on the analysed ordering
  Eigen::Map<Eigen::VectorXd> a(A_.valuePtr(), A_.nonZeros());
  a = -cq * fq_ - cv * fv_;
  for (int k : diagonal_) a[k] += 1.0;
  lu_.factorize(A_);
  ok_ = lu_.info() == Eigen::Success;
  return ok_;
}

void SparseNewtonMatrix::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  if (!ok_) {
    x.setConstant(std::numeric_limits<double>::quiet_NaN());
    return;
  }
  x = lu_.solve(b);
}

void SparseNewtonMatrix::solve(const Eigen::MatrixXd& B, Eigen::MatrixXd& X) const {
  if (!ok_) {
    X.setConstant(std::numeric_limits<double>::quiet_NaN());
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
