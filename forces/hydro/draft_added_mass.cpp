#include "forces/hydro/draft_added_mass.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "dynamics/added_mass.hpp"
#include "dynamics/kinematics.hpp"
#include "forces/hydro/added_mass.hpp"

namespace yardsim::forces::hydro {

using dynamics::Matrix6;
using dynamics::Vector3;

DraftAddedMassTable draftAddedMassTable(const PanelMesh& hull_B, const dynamics::Matrix3& R_WB,
                                        const std::vector<double>& drafts, double rho,
                                        double waterLevel) {
  if (drafts.empty()) throw std::invalid_argument("no drafts to tabulate the added mass at");
  for (std::size_t k = 0; k < drafts.size(); ++k)
    if (!(drafts[k] > (k == 0 ? 0.0 : drafts[k - 1])) || !std::isfinite(drafts[k]))
      throw std::invalid_argument("the drafts must be finite, > 0 and increasing");
  DraftAddedMassTable t;
  t.drafts = drafts;
  t.waterLevel = waterLevel;
  // (hull, attitude) => the keel point: the centroid of the vertices lowest in the world at that
  // attitude (a flat bottom's middle, a keel line's middle; not one corner, whose depth heel and
  // trim would swing)
  double zMin = std::numeric_limits<double>::infinity(), zMax = -zMin;
  for (const Vector3& v : hull_B.vertices) {
    zMin = std::min(zMin, (R_WB * v).z());
    zMax = std::max(zMax, (R_WB * v).z());
  }
  const double tol = 1e-9 * std::max(1.0, zMax - zMin);
  Vector3 sum = Vector3::Zero();
  int n = 0;
  for (const Vector3& v : hull_B.vertices)
    if ((R_WB * v).z() <= zMin + tol) {
      sum += v;
      ++n;
    }
  t.p_BK = sum / n;
  // (draft d) => X_WB with the origin over the world's and the keel point d below the level; A
  // about the origin, body axes, symmetrised
  for (const double d : drafts) {
    dynamics::Transform X_WB = dynamics::Transform::identity();
    X_WB.R = R_WB;
    X_WB.p = Vector3(0.0, 0.0, waterLevel - d - zMin);
    const Matrix6 A = floatingAddedMass(hull_B, X_WB, rho, waterLevel);
    t.A_B.push_back(dynamics::addedMassAboutOrigin(0.5 * (A + A.transpose()), Vector3::Zero()));
  }
  return t;
}

DraftAddedMass::DraftAddedMass(std::string name, const dynamics::Model& model, int body,
                               std::shared_ptr<const DraftAddedMassTable> table)
    : ForceProvider(std::move(name)), body_(body), table_(std::move(table)) {
  const std::string me = "added mass following the draft '" + this->name() + "': ";
  if (body_ < 1 || body_ >= model.nbodies)
    throw std::invalid_argument(me + "body " + std::to_string(body_) +
                                " is the world or outside the model");
  if (!table_ || table_->drafts.empty() || table_->drafts.size() != table_->A_B.size())
    throw std::invalid_argument(me +
                                "the table is empty or its drafts and matrices differ in number");
  if (model.hasAddedMass[static_cast<std::size_t>(body_)])
    throw std::invalid_argument(me + "the body has a constant added mass already");
}

double DraftAddedMass::draft(const dynamics::Transform& X_WB) const {
  return table_->waterLevel - X_WB.actPoint(table_->p_BK).z();
}

bool DraftAddedMass::interpolate(double d, Matrix6& A, Matrix6& dA) const {
  const auto& ds = table_->drafts;
  const auto& As = table_->A_B;
  if (!(d > 0.0)) {
    A.setZero();
    dA.setZero();
    return false;
  }
  if (d >= ds.back()) {
    A = As.back();
    dA.setZero();
    return true;
  }
  // (d) => the segment [d0, d1] holding it; below the first draft it starts from A = 0 at 0
  const std::size_t k =
      static_cast<std::size_t>(std::upper_bound(ds.begin(), ds.end(), d) - ds.begin());
  const double d0 = k == 0 ? 0.0 : ds[k - 1], d1 = ds[k];
  const double s = (d - d0) / (d1 - d0);
  if (k == 0) {
    A = s * As[0];
    dA = As[0] / d1;
  } else {
    A = (1.0 - s) * As[k - 1] + s * As[k];
    dA = (As[k] - As[k - 1]) / (d1 - d0);
  }
  return true;
}

Matrix6 DraftAddedMass::rate(const Stage& s) const {
  // (keel point's vertical velocity) => dd/dt = -v_z, then A' = dA/dd dd/dt
  Matrix6 A, dA;
  if (!interpolate(draft(s.data.X_WB[static_cast<std::size_t>(body_)]), A, dA))
    return Matrix6::Zero();
  const double ddot = -dynamics::pointVelocity(s.data, body_, table_->p_BK).z();
  return dA * ddot;
}

void DraftAddedMass::doEvaluate(const Stage& s, dynamics::ExternalForces& f,
                                Eigen::VectorXd& /*tau*/) const {
  // (A', V) => -A' V while A grows (entering), body frame about the origin; nothing while it
  // shrinks (leaving: the water keeps the momentum it had)
  const Matrix6 Adot = rate(s);
  if (!(Adot.trace() > 0.0)) return;
  const dynamics::Motion& V = s.data.V_B[static_cast<std::size_t>(body_)];
  f.addBodyFrame(body_, -(Adot * V));
}

double DraftAddedMass::doPower(const Stage& s) const {
  // (A', V) => entering: the force's power -V.A'V plus the change 1/2 V.A'V of the kinetic
  // energy that A' makes by itself, -1/2 V.A'V; leaving: that change alone, 1/2 V.A'V (both <= 0)
  const Matrix6 Adot = rate(s);
  const dynamics::Motion& V = s.data.V_B[static_cast<std::size_t>(body_)];
  const double e = 0.5 * V.dot(Adot * V);
  return Adot.trace() > 0.0 ? -e : e;
}

}  // namespace yardsim::forces::hydro
