#pragma once
// A body's infinite-frequency added mass following its draft (issue 18: a hull lowered into the
// water). The panel solver (added_mass.hpp, floatingAddedMass) computes A-infinity of the hull
// clipped at the still-water level at a few drafts at set-up; at every stage the body's draft
// (the depth of its keel point below the still-water level) picks the matrix by linear
// interpolation, from A = 0 at draft 0 (dry) to the deepest tabulated draft (held beyond it).
// The attitude is that of the body at set-up: heel and trim are not tabulated.
//
// The matrix goes onto the left-hand side: mechanics writes it into dynamics::Data::addedMass
// before the kernels run (mechanics/follow_draft.hpp). As a force provider this is the rest of
// the fluid's momentum d(A V)/dt = A V' + A' V while the body enters (A grows): the force -A' V,
// A' = dA/dd * dd/dt (von Karman's momentum form of water entry, a slamming force), in the body
// frame about the body origin; while it leaves (A shrinks) no force: the water keeps its
// momentum (the momentum form would push the body out of the water). With A varying the kinetic
// energy 1/2 V.(M + A)V changes by 1/2 V.A'V without any force, so the energy balance closes
// with power() = -1/2 V.A'V entering (the force's -V.A'V plus that change: the energy left in
// the spray and waves, Wagner's half) and 1/2 V.A'V leaving (the water's share, left behind).
// The keel point is the centroid of the hull's lowest vertices at set-up.
// Units SI: m, kg, kg m, kg m^2, N, W.
#include <memory>
#include <string>
#include <vector>

#include "dynamics/data.hpp"
#include "dynamics/model.hpp"
#include "forces/force_provider.hpp"
#include "forces/hydro/panel_mesh.hpp"

namespace yardsim::forces::hydro {

struct DraftAddedMassTable {
  std::vector<double> drafts;  ///< m, increasing, > 0 (A = 0 at draft 0 is implied)
  std::vector<dynamics::Matrix6>
      A_B;  ///< at each draft: body frame, about the body origin, [angular; linear]
  dynamics::Vector3 p_BK = dynamics::Vector3::Zero();  ///< keel point (centroid of the lowest hull
                                                       ///< vertices at set-up), body frame, m
  double waterLevel = 0.0;  ///< z of the still-water level, world frame, m
};

/// (hull in the body frame, the body's attitude R_WB at set-up, drafts (m, increasing, > 0), rho
/// kg/m^3, still-water level z) => A-infinity by the panel solver with the hull placed at each
/// draft (its keel point that far below the level, its origin over the world's, attitude R_WB);
/// throws PanelError (a bad mesh) or std::invalid_argument (drafts not increasing and positive).
DraftAddedMassTable draftAddedMassTable(const PanelMesh& hull_B, const dynamics::Matrix3& R_WB,
                                        const std::vector<double>& drafts, double rho,
                                        double waterLevel);

class DraftAddedMass final : public ForceProvider {
 public:
  /// (name, model, body index, its table); throws std::invalid_argument for a bad body or table.
  DraftAddedMass(std::string name, const dynamics::Model& model, int body,
                 std::shared_ptr<const DraftAddedMassTable> table);

  int body() const { return body_; }
  const DraftAddedMassTable& table() const { return *table_; }
  /// (X_WB) => the draft of the keel point, m (<= 0: dry)
  double draft(const dynamics::Transform& X_WB) const;
  /// (draft) => A by linear interpolation and its slope dA/dd (zero beyond the table), body
  /// frame about the origin; false when the body is dry (A = 0)
  bool interpolate(double draft, dynamics::Matrix6& A, dynamics::Matrix6& dA) const;

 protected:
  void doEvaluate(const Stage& s, dynamics::ExternalForces& f, Eigen::VectorXd& tau) const override;
  double doPower(const Stage& s) const override;

 private:
  // (stage) => A'(t) = dA/dd * dd/dt, body frame; zero when dry or beyond the table
  dynamics::Matrix6 rate(const Stage& s) const;
  int body_;
  std::shared_ptr<const DraftAddedMassTable> table_;
};

}  // namespace yardsim::forces::hydro
