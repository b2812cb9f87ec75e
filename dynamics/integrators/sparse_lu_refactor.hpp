#pragma once
// Eigen's SparseLU with a refactorisation that allocates nothing: refactorize(A), for a matrix with
// the pattern of the previous factorisation, computes the same LU as SparseLU::factorize(A) (the
// same panels, the same partial pivoting with its threshold, the same kernels in the same order:
// every value and pivot the same double and index) in the storage that factorisation left: the
// permuted copy of A, the L and U arrays (SparseLU's GlobalLU_t, kept at their size instead of
// shrunk to the first estimate and grown again) and the work arrays, kept here. Eigen 3.4's
// factorize makes those at every call (14 heap blocks on a 94-dof dense pattern).
// Only when L or U fill beyond every earlier factorisation (the pivots changed) does the
// refactorisation grow their arrays, as SparseLU does (counted by grownFactorisations()); a first
// call or another pattern goes through SparseLU::factorize (counted by fullFactorisations()).
// The solve, the permutations and the factors are SparseLU's.
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <cstddef>

namespace yardsim::dynamics {

class SparseLuRefactor
    : public Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> {
 public:
  using Matrix = Eigen::SparseMatrix<double>;
  using Lu = Eigen::SparseLU<Matrix, Eigen::COLAMDOrdering<int>>;

  /// (A) => SparseLU's ordering for A's pattern; the next refactorize() is a full one
  void analyzePattern(const Matrix& A) {
    Lu::analyzePattern(A);
    kept_ = false;
  }

  /// (A, compressed, analysed by analyzePattern) => its LU, info() Success or NumericalIssue (a
  /// zero pivot); as factorize(A), without allocating when A has the pattern of the last call
  void refactorize(const Matrix& A);

  /// How many calls went through SparseLU::factorize (the first, or a new pattern), and how many
  /// refactorisations had to grow L's or U's arrays.
  std::size_t fullFactorisations() const { return full_; }
  std::size_t grownFactorisations() const { return grown_; }

 private:
  // (A) => true when its pattern is the one kept (the storage fits it)
  bool samePattern(const Matrix& A) const;
  // (A) => factorize(A), the pattern and the work arrays kept for the next refactorisations
  void fullFactorisation(const Matrix& A);

  IndexVector outer_, inner_;  // A's pattern at the last full factorisation
  IndexVector segrep_, parent_, xplore_, repfnz_, panelLsub_, xprune_, marker_, relaxEnd_;
  ScalarVector dense_, tempv_;
  PermutationType ipermC_;                       // the inverse column permutation
  Eigen::Matrix<bool, Eigen::Dynamic, 1> mask_;  // the row permutation's determinant
  bool kept_ = false;
  std::size_t full_ = 0, grown_ = 0;
};

}  // namespace yardsim::dynamics
