#include "forces/hydro/rankine_td_model.hpp"

#include <chrono>
#include <string>

#include "forces/hydro/added_mass.hpp"
#include "forces/hydro/wetted_surface.hpp"

namespace yardsim::forces::hydro {

RankineTdModel::RankineTdModel(const PanelMesh& hull_B, const dynamics::Transform& X_WB,
                               const RankineTdSettings& settings)
    : settings_(settings) {
  if (!(settings.rho > 0.0) || !(settings.g > 0.0) || !(settings.depth > 0.0))
    throw PanelError("rankine_td: rho, g and depth must be > 0");
  // (hull in B, X_WB) => hull in W with the still-water level at z = 0, its wetted part
  const Vector3 level(0.0, 0.0, settings.waterLevel);
  PanelMesh hull_W = hull_B;
  for (Vector3& v : hull_W.vertices) v = X_WB.actPoint(v) - level;
  const PanelMesh wet = wettedSurface(hull_W);
  if (wet.panelCount() == 0) throw PanelError("rankine_td: the hull is dry at its mean position");
  origin_ = X_WB.p - level;
  R_WB_ = X_WB.R;
  // (wetted hull) => free-surface panels, then the mixed problem on both
  surface_ = buildFreeSurface(wet, settings.freeSurface);
  std::vector<Panel> body = buildPanels(wet);
  std::vector<Panel> fs = buildPanels(surface_.mesh);
  damping_ = Eigen::Map<const Eigen::VectorXd>(surface_.damping.data(),
                                               static_cast<Eigen::Index>(surface_.damping.size()));
  modes_ = modeNormals(body, origin_);
  problem_ = std::make_unique<MixedProblem>(std::move(body), std::move(fs), settings.depth);
  // (hull force functional W = [rho N^T diag(area), 0]: F = -int p n dS, p = -rho phi_t) => force
  // maps by the adjoint solve; A_inf = -forceFromBody N (the psi_j problem: Neumann N_j, Dirichlet
  // 0)
  const auto t0 = std::chrono::steady_clock::now();
  const int nb = problem_->bodyCount();
  Eigen::MatrixXd w = Eigen::MatrixXd::Zero(problem_->size(), 6);
  for (int k = 0; k < nb; ++k)
    w.row(k) = settings.rho * problem_->body()[static_cast<std::size_t>(k)].area * modes_.row(k);
  auto [fb, ff] = problem_->adjointMaps(w);
  forceFromBody_ = std::move(fb);
  forceFromSurface_ = std::move(ff);
  aInf_ = -(forceFromBody_ * modes_);
  mapSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

Eigen::Matrix<double, 6, 6> toBodyAxes(const Eigen::Matrix<double, 6, 6>& M_W,
                                       const Eigen::Matrix3d& R_WB) {
  Eigen::Matrix<double, 6, 6> R = Eigen::Matrix<double, 6, 6>::Zero();
  R.topLeftCorner<3, 3>() = R_WB;
  R.bottomRightCorner<3, 3>() = R_WB;
  return R.transpose() * M_W * R;
}

}  // namespace yardsim::forces::hydro
