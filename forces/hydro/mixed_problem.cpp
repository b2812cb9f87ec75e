#include "forces/hydro/mixed_problem.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "forces/hydro/rankine_integrals.hpp"

extern "C" {
// BLAS (Fortran calling convention): B <- alpha op(A)^-1 B for a triangular A, on the left
void dtrsm_(const char* side, const char* uplo, const char* transa, const char* diag, const int* m,
            const int* n, const double* alpha, const double* a, const int* lda, double* b,
            const int* ldb);
}

namespace yardsim::forces::hydro {

namespace {

double seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

}  // namespace

MixedProblem::MixedProblem(std::vector<Panel> body, std::vector<Panel> freeSurface, double depth)
    : body_(std::move(body)), surface_(std::move(freeSurface)), depth_(depth) {
  const auto nb = static_cast<Eigen::Index>(body_.size()),
             nf = static_cast<Eigen::Index>(surface_.size());
  const Eigen::Index n = nb + nf;
  const bool image = std::isfinite(depth_);
  if (image) {
    for (const Panel& p : body_) {
      for (int k = 0; k < p.count; ++k) {
        if (!(p.vertices[static_cast<std::size_t>(k)].z() > -depth_)) {
          throw PanelError("mixed problem: the hull reaches the sea bed (a vertex at z = " +
                           std::to_string(p.vertices[static_cast<std::size_t>(k)].z()) +
                           " m, depth " + std::to_string(depth_) + " m)");
        }
      }
    }
  }
  const auto t0 = std::chrono::steady_clock::now();
  system_.resize(n, n);
  fromBody_.resize(n, nb);
  fromSurface_.resize(n, nf);
  // (panel j, collocation points x_i and their sea-bed images) => column j of M and of R_b or R_f
  const auto panel = [&](Eigen::Index j) -> const Panel& {
    return j < nb ? body_[static_cast<std::size_t>(j)] : surface_[static_cast<std::size_t>(j - nb)];
  };
  for (Eigen::Index j = 0; j < n; ++j) {
    const Panel& pj = panel(j);
    for (Eigen::Index i = 0; i < n; ++i) {
      const Vector3& x = panel(i).centroid;
      PanelIntegrals v = panelIntegrals(pj, x);
      if (image) {
        const PanelIntegrals w = panelIntegrals(pj, Vector3(x.x(), x.y(), -2.0 * depth_ - x.z()));
        v.source += w.source;
        v.dipole += w.dipole;
      }
      const double self = i == j ? 2.0 * std::numbers::pi : 0.0;
      if (j < nb) {
        system_(i, j) = self - v.dipole;
        fromBody_(i, j) = -v.source;
      } else {
        system_(i, j) = v.source;
        fromSurface_(i, j - nb) = v.dipole - self;
      }
    }
  }
  assemblySeconds_ = seconds(t0);
  const auto t1 = std::chrono::steady_clock::now();
  lu_.emplace(system_);
  factorSeconds_ = seconds(t1);
}

void MixedProblem::solve(const Eigen::Ref<const Eigen::MatrixXd>& bodyNormal,
                         const Eigen::Ref<const Eigen::MatrixXd>& surfacePotential,
                         Eigen::Ref<Eigen::MatrixXd> rhs, Eigen::Ref<Eigen::MatrixXd> out) const {
  // (a, p) => R_b a + R_f p, then u = M^-1 rhs by the LU's back-substitution
  rhs.noalias() = fromBody_ * bodyNormal;
  rhs.noalias() += fromSurface_ * surfacePotential;
  if (rhs.cols() != 1) {
    out = lu_->solve(rhs);
    return;
  }
  // (one column: a panel step) => P rhs, then the two triangles in place on that column: Eigen's
  // vector substitutions work in the column itself, where its matrix solve packs blocks from the
  // heap (a solve as PartialPivLU::solve does; the same to round-off)
  auto u = out.col(0);
  u = lu_->permutationP() * rhs.col(0);
  lu_->matrixLU().triangularView<Eigen::UnitLower>().solveInPlace(u);
  lu_->matrixLU().triangularView<Eigen::Upper>().solveInPlace(u);
}

Eigen::MatrixXd MixedProblem::surfaceMap() const {
  // (R_f) => L^-1 P R_f over all rows, then U_ff^-1 on its last N_f rows
  const int n = size(), nf = surfaceCount(), nb = bodyCount(), columns = nf;
  if (nf == 0) return Eigen::MatrixXd::Zero(0, 0);
  Eigen::MatrixXd x = lu_->permutationP() * fromSurface_;
  const Eigen::MatrixXd& lu = lu_->matrixLU();
  const double one = 1.0;
  dtrsm_("L", "L", "N", "U", &n, &columns, &one, lu.data(), &n, x.data(), &n);
  dtrsm_("L", "U", "N", "N", &nf, &columns, &one, lu.data() + static_cast<Eigen::Index>(nb) * (n + 1),
         &n, x.data() + nb, &n);
  return x.bottomRows(nf);
}

std::pair<Eigen::MatrixXd, Eigen::MatrixXd> MixedProblem::adjointMaps(
    const Eigen::MatrixXd& w) const {
  // (w) => z = M^-T w, then (z^T R_b, z^T R_f)
  const Eigen::MatrixXd z = lu_->transpose().solve(w);
  return {z.transpose() * fromBody_, z.transpose() * fromSurface_};
}

Eigen::MatrixXd MixedProblem::solve(const Eigen::MatrixXd& bodyNormal,
                                    const Eigen::MatrixXd& surfacePotential) const {
  Eigen::MatrixXd rhs(size(), bodyNormal.cols()), out(size(), bodyNormal.cols());
  solve(bodyNormal, surfacePotential, rhs, out);
  return out;
}

}  // namespace yardsim::forces::hydro
