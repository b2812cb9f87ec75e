#pragma once
// The Newton (iteration) matrix A = I - c_q F_q - c_v F_v of an implicit integrator, sparse, for a
// system whose Jacobian has structure (column_colouring.hpp; a lumped-mass line couples each node
// to its neighbours only): F_q (through the chart at q_n) and F_v by finite differences with one
// evaluation per colour for q and one for v instead of one per dof, stored on the pattern
// (compressed columns), and factorised as a band matrix with a border (bordered_band_lu.hpp:
// lines hanging from a few rigid bodies have that shape; linear in the nodes, where a dense LU
// is cubic) or, for any other pattern, by Eigen's SparseLU with the COLAMD ordering analysed once
// at construction, refactorised in the storage of the first factorisation (sparse_lu_refactor.hpp:
// the same LU, without allocating; docs/performance.md).
// The blocks a system gives in closed form (JacobianBlocks: a lumped line's nodes among
// themselves) are written from the system's blockJacobian instead, and a column all of whose
// entries lie in such blocks is left out of the colours: the differences are then needed only for
// the columns of the rigid dofs and of the nodes next to them. The 3 x 1 blocks (a line's end node
// against a rigid dof of the body at its end) overwrite those entries of the rigid columns at
// every refresh of the blocks; the columns' other rows keep their differences.
// F is the accelerations (1/s^2 per m or rad, 1/s per m/s or rad/s); A is dimensionless.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "dynamics/configuration.hpp"
#include "dynamics/integrators/bordered_band_lu.hpp"
#include "dynamics/integrators/column_colouring.hpp"
#include "dynamics/integrators/sparse_lu_refactor.hpp"
#include "dynamics/model.hpp"

namespace yardsim::dynamics {

class SparseNewtonMatrix {
 public:
  // (model, pattern of F_q and F_v, blocks given in closed form or null) => the colouring of the
  // columns the blocks do not cover, A's structure (the pattern and the diagonal) and its
  // ordering; throws std::invalid_argument when the pattern is not nv x nv or a block leaves it.
  // band: false keeps SparseLU even for a bordered band pattern (tests)
  SparseNewtonMatrix(const Model& model, const JacobianPattern& pattern,
                     const JacobianBlocks* blocks = nullptr, bool band = true);

  const ColumnColouring& colouring() const { return colouring_; }
  int nonZeros() const { return static_cast<int>(A_.nonZeros()); }

  // (accel(q', v', qMoved, F'): the accelerations at a perturbed state; q_n, the chart step
  // delta, q_{n+1} = q_n (+) delta, v_{n+1}, F at (q_{n+1}, v_{n+1})) => F_q and F_v on the
  // pattern, by forward differences with the dense path's step sizes; returns the evaluations
  template <class Accel>
  int form(Accel&& accel, const Eigen::VectorXd& q, const Eigen::VectorXd& delta,
           const Eigen::VectorXd& qNew, const Eigen::VectorXd& vNew, const Eigen::VectorXd& f) {
    const double eps = 1.4901161193847656e-08;  // sqrt(machine epsilon), as the dense path
    for (const std::vector<int>& cols : colouring_.columns) {
      // (one colour) => its columns of F_q: every dof of the colour moved at once
      deltaP_ = delta;
      for (int j : cols) {
        step_[j] = eps * std::max(1.0, std::abs(delta[j]));
        deltaP_[j] += step_[j];
      }
      integrate(model_, q, deltaP_, 1.0, qp_);
      accel(qp_, vNew, true, fp_);
      scatter(cols, f, fq_);
      // (one colour) => its columns of F_v
      vp_ = vNew;
      for (int j : cols) {
        step_[j] = eps * std::max(1.0, std::abs(vNew[j]));
        vp_[j] += step_[j];
      }
      accel(qNew, vp_, false, fp_);
      scatter(cols, f, fv_);
    }
    return 2 * colouring_.count();
  }

  // the blocks' values, to be filled by AccelerationSource::blockJacobian (3x3 each, then the
  // 3 x 1 blocks in their first columns)
  bool hasBlocks() const { return !blockIndex_.empty(); }
  std::vector<Eigen::Matrix3d>& blockDq() { return dq_; }
  std::vector<Eigen::Matrix3d>& blockDv() { return dv_; }
  // (blocks filled, their switch signature) => written into F_q and F_v; true when the signature
  // differs from the one last written (a segment went slack or taut, a node touched the bed)
  bool applyBlocks(std::uint64_t signature);

  // (c_q, c_v) => LU of A = I - c_q F_q - c_v F_v; false when it is singular
  // (bordered band: bordered_band_lu.hpp; else SparseLU)
  bool factorise(double cq, double cv);

  // Column groups for factorise(c_q, c_v, maps): the k <= 6 dofs of a joint from `first`
  // (CVODE's chart kinematics, chart_newton_system.hpp). (first, k) => true when those columns
  // have the same rows in A (then F_q M keeps A's structure); false and nothing kept otherwise
  bool groupColumns(int first, int k);
  // (c_q, c_v, per group a matrix M_g, its top-left k x k used) => LU of
  // A = I - c_q F_q M - c_v F_v, M block diagonal: M_g on the groups' columns, I elsewhere
  bool factorise(double cq, double cv, const std::vector<Eigen::Matrix<double, 6, 6>>& maps);
  // (c, x) => y += c F_q x (F_q as formed, without M)
  void addFq(double c, const Eigen::VectorXd& x, Eigen::VectorXd& y) const;
  // (b) => x = A^-1 b (NaN when the last factorisation failed: Newton then gives up)
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;
  void solve(const Eigen::MatrixXd& B, Eigen::MatrixXd& X) const;
  // true when A is factorised as a bordered band matrix (bordered_band_lu.hpp), false: SparseLU
  bool banded() const { return banded_; }
  // the SparseLU path's factorisation (its counts of full and grown factorisations; tests)
  const SparseLuRefactor& sparseLu() const { return lu_; }

  // F_q and F_v as dense matrices (tests)
  Eigen::MatrixXd denseFq() const;
  Eigen::MatrixXd denseFv() const;

 private:
  // (columns of one colour, F, fp_) => their entries (fp - F) / step on the pattern
  void scatter(const std::vector<int>& cols, const Eigen::VectorXd& f, Eigen::VectorXd& values);

  const Model& model_;
  ColumnColouring colouring_;
  Eigen::SparseMatrix<double> A_;  // structure fixed at construction; values per factorise
  std::vector<int> diagonal_;      // per column: the index of its diagonal entry in A_'s values
  Eigen::VectorXd fq_, fv_;        // F_q, F_v on A_'s structure
  std::vector<std::array<int, 2>> groups_;  // column groups (first, k) of factorise(.., maps)
  Eigen::VectorXd fqm_;                     // F_q M on A_'s structure
  // (A's values set) => the numeric LU, ok_
  bool factoriseValues();
  Eigen::VectorXd step_, deltaP_, qp_, vp_, fp_;
  mutable Eigen::VectorXd y_, work_;  // solve(): the permuted right-hand side, L's work vector
  std::vector<std::array<int, 9>> blockIndex_;   // per block: its entries in A_'s values, by column
  std::vector<std::array<int, 3>> columnIndex_;  // per 3 x 1 block: its entries, -1 outside
  std::vector<Eigen::Matrix3d> dq_, dv_;
  std::uint64_t signature_ = 0;
  bool applied_ = false;
  bool ok_ = false;
  BorderedBandLu band_;  // when A is a band matrix but for a few rows and columns
  bool banded_ = false;
  SparseLuRefactor lu_;  // SparseLU, refactorised in its first factorisation's storage
};

}  // namespace yardsim::dynamics
