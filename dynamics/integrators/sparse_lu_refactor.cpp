// SparseLuRefactor::refactorize is SparseLU<>::factorize of Eigen 3.4.0
// (Eigen/src/SparseLU/SparseLU.h) with its storage kept between calls; that function is
// Copyright (C) 2012 Désiré Nuentsa-Wakam <desire.nuentsa_wakam@inria.fr>
// Copyright (C) 2012-2014 Gael Guennebaud <gael.guennebaud@inria.fr>
// and this file, as Eigen's, is subject to the terms of the Mozilla Public License v. 2.0. If a
// copy of the MPL was not distributed with this file, You can obtain one at
// http://mozilla.org/MPL/2.0/.
#include "dynamics/integrators/sparse_lu_refactor.hpp"

#include <algorithm>

namespace yardsim::dynamics {

using Eigen::Index;

bool SparseLuRefactor::samePattern(const Matrix& A) const {
  if (!kept_ || !A.isCompressed() || A.rows() != m_mat.rows() || A.cols() != m_mat.cols() ||
      A.nonZeros() != inner_.size())
    return false;
  return std::equal(A.outerIndexPtr(), A.outerIndexPtr() + A.cols() + 1, outer_.data()) &&
         std::equal(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros(), inner_.data());
}

void SparseLuRefactor::fullFactorisation(const Matrix& A) {
  // (A) => SparseLU's factorisation, which sizes m_mat and m_glu; then A's pattern and the work
  // arrays at their sizes, and the inverse column permutation, for the refactorisations
  factorize(A);
  ++full_;
  kept_ = m_factorizationIsOk && A.isCompressed();
  if (!kept_) return;
  Index m = A.rows(), rowblk = m;  // (LUnumTempV takes references)
  const Index n = A.cols(), maxpanel = m_perfv.panel_size * m;
  outer_ = Eigen::Map<const IndexVector>(A.outerIndexPtr(), n + 1);
  inner_ = Eigen::Map<const IndexVector>(A.innerIndexPtr(), A.nonZeros());
  for (IndexVector* v : {&segrep_, &parent_, &xplore_}) v->resize(m);
  repfnz_.resize(maxpanel);
  panelLsub_.resize(maxpanel);
  xprune_.resize(n);
  marker_.resize(m * Eigen::internal::LUNoMarker);
  relaxEnd_.resize(n);
  dense_.resize(maxpanel);
  tempv_.resize(Eigen::internal::LUnumTempV(m, m_perfv.panel_size, m_perfv.maxsuper, rowblk));
  ipermC_ = m_perm_c.inverse();
  mask_.resize(m);
}

void SparseLuRefactor::refactorize(const Matrix& A) {
  using Eigen::internal::emptyIdxLU;
  if (!samePattern(A) || !m_analysisIsOk) {
    fullFactorisation(A);
    return;
  }
  m_isInitialized = true;
  // (A's values) => the column-permuted copy m_mat: SparseLU permutes only its column pointers,
  // so its values are A's in A's order
  std::copy(A.valuePtr(), A.valuePtr() + A.nonZeros(), m_mat.valuePtr());
  const Index m = m_mat.rows(), n = m_mat.cols();
  // (SparseLU's memInit skipped: L's and U's arrays and their bounds in m_glu are those the last
  // factorisations grew them to) => the work arrays reset as factorize sets them
  segrep_.setZero();
  parent_.setZero();
  xplore_.setZero();
  xprune_.setZero();
  marker_.setZero();
  repfnz_.setConstant(-1);
  panelLsub_.setConstant(-1);
  dense_.setZero();
  tempv_.setZero();
  const Index expansions = m_glu.num_expansions;
  // (the elimination tree) => the initial relaxed supernodes
  if (m_symmetricmode)
    Base::heap_relax_snode(n, m_etree, m_perfv.relax, marker_, relaxEnd_);
  else
    Base::relax_snode(n, m_etree, m_perfv.relax, marker_, relaxEnd_);
  m_perm_r.indices().setConstant(-1);
  marker_.setConstant(-1);
  m_detPermR = 1;
  m_glu.supno(0) = emptyIdxLU;
  m_glu.xsup.setConstant(0);
  m_glu.xsup(0) = m_glu.xlsub(0) = m_glu.xusub(0) = m_glu.xlusup(0) = Index(0);
  // (one panel at a time: a relaxed supernode at the bottom of the elimination tree, or
  // panel_size contiguous columns) => its symbolic and numeric factorisation, column by column
  auto fail = [this]() {
    m_info = Eigen::NumericalIssue;
    m_factorizationIsOk = false;
  };
  Index pivrow = 0, nseg1 = 0, nseg = 0;
  for (Index jcol = 0; jcol < n;) {
    Index panelSize = m_perfv.panel_size, k = jcol + 1;
    for (; k < std::min(jcol + panelSize, n); k++)
      if (relaxEnd_(k) != emptyIdxLU) {
        panelSize = k - jcol;
        break;
      }
    if (k == n) panelSize = n - jcol;
    Base::panel_dfs(m, panelSize, jcol, m_mat, m_perm_r.indices(), nseg1, dense_, panelLsub_,
                    segrep_, repfnz_, xprune_, marker_, parent_, xplore_, m_glu);
    Base::panel_bmod(m, panelSize, jcol, nseg1, dense_, tempv_, segrep_, repfnz_, m_glu);
    for (Index jj = jcol; jj < jcol + panelSize; jj++) {
      k = (jj - jcol) * m;
      nseg = nseg1;
      Eigen::VectorBlock<IndexVector> panelLsubK(panelLsub_, k, m);
      Eigen::VectorBlock<IndexVector> repfnzK(repfnz_, k, m);
      if (Base::column_dfs(m, jj, m_perm_r.indices(), m_perfv.maxsuper, nseg, panelLsubK, segrep_,
                           repfnzK, xprune_, marker_, parent_, xplore_, m_glu) != 0)
        return fail();
      Eigen::VectorBlock<ScalarVector> denseK(dense_, k, m);
      Eigen::VectorBlock<IndexVector> segrepK(segrep_, nseg1, m - nseg1);
      if (Base::column_bmod(jj, (nseg - nseg1), denseK, tempv_, segrepK, repfnzK, jcol, m_glu) != 0)
        return fail();
      if (Base::copy_to_ucol(jj, nseg, segrep_, repfnzK, m_perm_r.indices(), denseK, m_glu) != 0)
        return fail();
      // (a zero pivot: numerically singular) => failed, without SparseLU's message
      if (Base::pivotL(jj, m_diagpivotthresh, m_perm_r.indices(), ipermC_.indices(), pivrow,
                       m_glu) != 0)
        return fail();
      if (pivrow != jj) m_detPermR = -m_detPermR;
      Base::pruneL(jj, m_perm_r.indices(), pivrow, nseg, segrep_, repfnzK, xprune_, m_glu);
      for (Index i = 0; i < nseg; i++) repfnzK(segrep_(i)) = emptyIdxLU;
    }
    jcol += panelSize;
  }
  // (the row permutation) => its determinant, as PermutationBase::determinant in mask_ (m_detPermC
  // is the analysed column permutation's, unchanged)
  m_detPermR = 1;
  mask_.setConstant(false);
  const auto& pr = m_perm_r.indices();
  for (Index r = 0; r < m; ++r) {
    if (mask_[r]) continue;
    mask_[r] = true;
    for (Index k = pr[r]; k != r; k = pr[k]) {
      mask_[k] = true;
      m_detPermR = -m_detPermR;
    }
  }
  if (m_glu.num_expansions != expansions) ++grown_;
  // (L's and U's arrays) => their counts, L's subscripts permuted, the supernodal L and the
  // column-major U mapped on them
  Base::countnz(n, m_nnzL, m_nnzU, m_glu);
  Base::fixupL(n, m_perm_r.indices(), m_glu);
  m_Lstore.setInfos(m, n, m_glu.lusup, m_glu.xlusup, m_glu.lsub, m_glu.xlsub, m_glu.supno,
                    m_glu.xsup);
  new (&m_Ustore) Eigen::MappedSparseMatrix<double, Eigen::ColMajor, int>(
      m, n, m_nnzU, m_glu.xusub.data(), m_glu.usub.data(), m_glu.ucol.data());
  m_info = Eigen::Success;
  m_factorizationIsOk = true;
}

}  // namespace yardsim::dynamics
