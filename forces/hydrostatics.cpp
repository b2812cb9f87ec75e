#include "forces/hydrostatics.hpp"

#include <cmath>
#include <cstring>
#include <stdexcept>

#include "dynamics/kinematics.hpp"
#include "dynamics/rotation.hpp"

namespace yardsim::forces {

using dynamics::Vector3;

Hydrostatics::Hydrostatics(std::string name, const dynamics::Model& model, int body,
                           TriangleMesh hull, std::shared_ptr<const AiryWaves> sea,
                           bool incidentPressure)
    : ForceProvider(std::move(name)),
      body_(body),
      hull_(std::move(hull)),
      sea_(std::move(sea)),
      calm_(sea_ ? sea_->water() : WaterProperties{}),
      incident_(incidentPressure) {
  if (body_ < 1 || body_ >= model.nbodies)
    throw std::invalid_argument("hydrostatics '" + this->name() + "': body " +
                                std::to_string(body_) + " is the world or outside the model's " +
                                std::to_string(model.nbodies) + " bodies");
  if (!sea_) throw std::invalid_argument("hydrostatics '" + this->name() + "': no sea given");
  try {
    checkClosedMesh(hull_);
  } catch (const MeshError& e) {
    throw std::invalid_argument("hydrostatics '" + this->name() + "': " + e.what());
  }
  solid_ = solidProperties(hull_);
  double zMin = hull_.vertices.front().z();
  for (const Vector3& v : hull_.vertices) zMin = std::min(zMin, v.z());
  keel_B_ = Vector3(solid_.centroid.x(), solid_.centroid.y(), zMin);
  // (tree) => the body and every body below it (parent[i] < i)
  std::vector<bool> in(static_cast<std::size_t>(model.nbodies), false);
  in[static_cast<std::size_t>(body_)] = true;
  for (int i = body_; i < model.nbodies; ++i)
    if (i == body_ || in[static_cast<std::size_t>(model.parent[i])]) {
      in[static_cast<std::size_t>(i)] = true;
      subtree_.push_back(i);
    }
}

std::unique_ptr<ProviderScratch> Hydrostatics::makeScratch() const {
  return std::make_unique<Scratch>(hull_, sea_->size());
}

SubmergedProperties Hydrostatics::submerged(const Stage& s, const AiryWaves& surface,
                                            SubmergedIntegrals which) const {
  static_assert(sizeof(dynamics::Transform) == 12 * sizeof(double), "a pose is 12 doubles");
  std::unique_ptr<ProviderScratch> temporary;
  Scratch& scratch = scratchOf<Scratch>(s, temporary);
  const dynamics::Transform& X = s.data.X_WB[body_];
  // (the sea before its waves start, or without waves) => calm water, the same doubles
  const AiryWaves& at =
      &surface == sea_.get() && (sea_->calm() || sea_->ramp(s.t) == 0.0) ? calm_ : surface;
  Scratch::Last(&ring)[2] = scratch.last[&at == &calm_ ? 1 : 0];
  // (the same surface, time and pose, bit for bit, and the integrals asked for) => the same
  // clipping
  const bool all = which == SubmergedIntegrals::All;
  for (const Scratch::Last& e : ring)
    if (e.sea == &at && std::memcmp(&e.t, &s.t, sizeof(double)) == 0 &&
        std::memcmp(&e.X_WB, &X, sizeof X) == 0 && (e.all || !all))
      return e.p;
  // (else) => clip, kept in place of an empty or force-only entry (the older of two), else of
  // the older: a step's end clipping with every integral outlives the next step's stages
  const auto rank = [](const Scratch::Last& e) { return e.sea == nullptr ? 0 : e.all ? 2 : 1; };
  const int r0 = rank(ring[0]), r1 = rank(ring[1]);
  Scratch::Last& last = r0 < r1 || (r0 == r1 && ring[0].when <= ring[1].when) ? ring[0] : ring[1];
  last.sea = &at;
  last.t = s.t;
  last.X_WB = X;
  last.p = integrateSubmerged(hull_, X, at, s.t, scratch.ws, false, which);
  last.all = all;
  last.when = ++scratch.clippings;
  return last.p;
}

void Hydrostatics::doEvaluate(const Stage& s, dynamics::ExternalForces& f,
                              Eigen::VectorXd& /*tau*/) const {
  // (X_WB, sea, t) => clipped hull, pressure force and moment about the world origin
  const SubmergedProperties p = submerged(s, surface(), SubmergedIntegrals::Force);
  dynamics::Force F_W;
  F_W << p.moment, p.force;
  f.addWorldFrame(body_, F_W);
}

double Hydrostatics::doPotentialEnergy(const Stage& s) const {
  const SubmergedProperties c = submerged(s, calm_);
  const WaterProperties& w = calm_.water();
  return w.density * w.gravity * c.volume * (w.level - c.centreOfBuoyancy.z());
}

double Hydrostatics::doPower(const Stage& s) const {
  if (sea_->calm() || !incident_) return 0.0;
  // (calm water: every integral, since the energy at the step's end asks for the same clipping)
  const SubmergedProperties c = submerged(s, calm_, SubmergedIntegrals::All);
  const SubmergedProperties w = submerged(s, *sea_, SubmergedIntegrals::Force);
  const dynamics::Motion V_W = dynamics::bodyVelocityWorld(s.data, body_);  // [omega; v at origin]
  return (w.moment - c.moment).dot(V_W.head<3>()) + (w.force - c.force).dot(V_W.tail<3>());
}

HydrostaticReport Hydrostatics::report(const Stage& s) const {
  const dynamics::Transform& X = s.data.X_WB[body_];
  HydrostaticReport r;
  r.submerged = submerged(s, surface());
  const WaterProperties& w = sea_->water();
  r.displacement = w.density * r.submerged.volume;
  r.draft = w.level - X.actPoint(keel_B_).z();
  const Vector3 rpy = dynamics::eulerAngles(X.R);
  r.heel = rpy.x();
  r.trim = rpy.y();
  // (centre of mass of the body and its subtree, waterplane inertia about the heading axes) => GM
  double m = 0.0, mz = 0.0;
  for (int i : subtree_) {
    const dynamics::SpatialInertia& I = s.model.inertias[i];
    m += I.mass;
    mz += I.mass * s.data.X_WB[i].actPoint(I.com).z();
  }
  const double zG = m > 0 ? mz / m : X.p.z();
  const double V = r.submerged.volume;
  if (V > 0.0) {
    const Eigen::Vector2d e(X.R(0, 0), X.R(1, 0));  // the body's x axis, horizontal
    const Eigen::Vector2d ex =
        e.norm() > 1e-12 ? Eigen::Vector2d(e.normalized()) : Eigen::Vector2d(1, 0);
    const Eigen::Vector2d ey(-ex.y(), ex.x());
    const Eigen::Matrix2d& J = r.submerged.waterplaneInertia;
    // transverse (rolling about the longitudinal axis): int (distance across)^2 = ey^T J ey
    const double base = r.submerged.centreOfBuoyancy.z() - zG;
    r.gmTransverse = base + ey.dot(J * ey) / V;
    r.gmLongitudinal = base + ex.dot(J * ex) / V;
  } else {
    r.gmTransverse = r.gmLongitudinal = 0.0;
  }
  return r;
}

}  // namespace yardsim::forces
