#include "forces/hydro/mixed_problem.hpp"

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "forces/hydro/dense_solve.hpp"
#include "forces/hydro/rankine_integrals.hpp"

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
  Eigen::MatrixXd system(n, n);
  map_.resize(n, n);  // (first R = [R_b R_f], then A = M^-1 R in its place)
  // (panel j, collocation points x_i and their sea-bed images) => column j of M and of R
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
        system(i, j) = self - v.dipole;
        map_(i, j) = -v.source;
      } else {
        system(i, j) = v.source;
        map_(i, j) = v.dipole - self;
      }
    }
  }
  // (a degenerate panel: NaN or infinite integrals) => refused, naming the two panels
  const auto name = [&](Eigen::Index k) {
    return k < nb ? "hull panel " + std::to_string(k)
                  : "free-surface panel " + std::to_string(k - nb);
  };
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index i = 0; i < n; ++i)
      if (!std::isfinite(system(i, j)) || !std::isfinite(map_(i, j)))
        throw PanelError("mixed problem: the influence integral of " + name(j) +
                         " at the centroid of " + name(i) +
                         " is not finite (a degenerate panel: zero area or coincident vertices)");
  assemblySeconds_ = seconds(t0);
  const auto t1 = std::chrono::steady_clock::now();
  try {
    solveInPlace(system, map_);  // (M, R) => A = M^-1 R
  } catch (const std::runtime_error& e) {
    throw PanelError(std::string("mixed problem: the influence matrix is singular (coincident or "
                                 "degenerate panels): ") +
                     e.what());
  }
  factorSeconds_ = seconds(t1);
}

void MixedProblem::solve(const Eigen::Ref<const Eigen::MatrixXd>& bodyNormal,
                         const Eigen::Ref<const Eigen::MatrixXd>& surfacePotential,
                         Eigen::Ref<Eigen::MatrixXd> out) const {
  // (a, p) => u = A_b a + A_f p
  out.noalias() = map_.leftCols(bodyCount()) * bodyNormal;
  out.noalias() += map_.rightCols(surfaceCount()) * surfacePotential;
}

std::pair<Eigen::MatrixXd, Eigen::MatrixXd> MixedProblem::adjointMaps(
    const Eigen::MatrixXd& w) const {
  // (w) => (w^T A_b, w^T A_f)
  return {w.transpose() * map_.leftCols(bodyCount()),
          w.transpose() * map_.rightCols(surfaceCount())};
}

Eigen::MatrixXd MixedProblem::solve(const Eigen::MatrixXd& bodyNormal,
                                    const Eigen::MatrixXd& surfacePotential) const {
  Eigen::MatrixXd out(size(), bodyNormal.cols());
  solve(bodyNormal, surfacePotential, out);
  return out;
}

}  // namespace yardsim::forces::hydro
