#pragma once
// The LU of a sparse matrix that is a band matrix once a few rows and columns (its border) are
// set aside: A = P^T [B C; D E] P with B of half-bandwidth w (the interior, in A's own order) and
// E dense r x r (the border). This is the shape of an implicit integrator's Newton matrix when
// lumped-mass lines hang from a few rigid bodies: each line's nodes couple only to their
// neighbours (w = 5 for 3-dof nodes, 8 with bending), the rigid dofs to the nodes next to them.
// B is factorised by band Gaussian elimination with partial pivoting (the layout and algorithm
// of LAPACK's dgbtf2/dgbtrs, its upper band growing to 2w), the border through the Schur
// complement S = E - D B^-1 C (dense, partial pivoting). Cost per factorisation
// O(n w^2 + n w r + r^3), per solve O(n w + n r + r^2): linear in n, where Eigen's supernodal
// SparseLU costs a few hundred ns per row on such a matrix and grows faster than n with it
// (docs/performance.md). Allocation-free after analyse(). Dimensionless (A's units).
#include <Eigen/Core>
#include <Eigen/LU>
#include <Eigen/SparseCore>
#include <cstdint>
#include <vector>

namespace yardsim::dynamics {

class BorderedBandLu {
 public:
  // (A's structure, compressed columns; the largest half-bandwidth and border accepted) => true
  // when A has that shape: the border is chosen greedily among the dofs with entries farther than
  // maxBand from the diagonal (most such entries first) until none is left; false (and nothing
  // usable) when the border would exceed maxBorder or A is not square
  bool analyse(const Eigen::SparseMatrix<double>& A, int maxBand = 12, int maxBorder = 64);
  // (A's values on the analysed structure) => factorised; false when a pivot is zero (singular)
  bool factorise(const Eigen::SparseMatrix<double>& A);
  // (b) => x = A^-1 b; x sized like b (resized once)
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;

  int bandwidth() const { return w_; }
  int border() const { return r_; }

 private:
  // (interior right-hand side y, in place) => B^-1 y by the band factors and their pivots
  void bandSolve(double* y) const;
  double& band(int i, int j) { return ab_[static_cast<std::size_t>(j) * ld_ + kv_ + i - j]; }
  double band(int i, int j) const { return ab_[static_cast<std::size_t>(j) * ld_ + kv_ + i - j]; }

  int n_ = 0, ni_ = 0, r_ = 0, w_ = 0, kv_ = 0;
  std::size_t ld_ = 0;
  std::vector<int> interior_, border_;  // new index => A's index
  // per nonzero of A: 0 band, 1 C, 2 D, 3 E; and its offset in that store
  std::vector<std::uint8_t> kind_;
  std::vector<std::size_t> at_;
  std::vector<double> ab_;  // B's band, column-major, ld_ = 3 w + 1 rows (LAPACK's AB)
  std::vector<int> pivot_;
  Eigen::MatrixXd C_, D_, E_;  // C becomes X = B^-1 C; E becomes S
  Eigen::PartialPivLU<Eigen::MatrixXd> luS_;
  mutable Eigen::VectorXd yi_, yb_, s_;
};

}  // namespace yardsim::dynamics
