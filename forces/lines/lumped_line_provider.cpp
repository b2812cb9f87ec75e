#include "forces/lines/lumped_line_provider.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "dynamics/kinematics.hpp"
#include "forces/lines/catenary.hpp"
#include "forces/lines/lumped_line_statics.hpp"

namespace yardsim::forces {

using dynamics::Vector3;

std::string lumpedNodeName(const std::string& line, int i) {
  return line + ".node" + std::to_string(i);
}

std::vector<LumpedNodeBody> lumpedLineNodes(const LumpedLine& line, const std::string& name,
                                            const Vector3& pA, const Vector3& pB) {
  const LumpedLineProperties& p = line.properties();
  const int n = p.segments;
  const double area = 0.25 * std::numbers::pi * p.diameter * p.diameter;
  // (ends) => the elastic catenary in the vertical plane through them, on the bed when the anchor
  // lies on it; its points at the nodes' unstretched arc lengths
  const Vector3 d = pB - pA;
  const double xf = std::hypot(d.x(), d.y());
  CatenaryParameters c{
      p.length, p.ea, line.weightPerLength(),
      p.seabed && std::abs(pA.z() - p.seabedZ) < 1e-9 * p.length && line.weightPerLength() > 0.0,
      0.0};
  CatenarySolution sol;
  const bool curved = xf > 1e-9 * p.length && catenaryParameterError(c)[0] == '\0';
  if (curved) sol = solveCatenary(c, xf, d.z());
  const bool onCatenary = curved && sol.status == CatenaryStatus::Converged;
  const Vector3 eh = xf > 0.0 ? Vector3(d.x() / xf, d.y() / xf, 0.0) : Vector3::UnitX();
  Eigen::Matrix3Xd r(3, n + 1);
  for (int i = 0; i <= n; ++i) {
    const double s = line.segmentLength() * i;
    r.col(i) = pA + (s / p.length) * d;  // (no catenary) => the straight chord
    if (onCatenary) {
      const CatenaryPoint pt = catenaryPoint(c, sol, xf, s);
      r.col(i) = pA + pt.x * eh + pt.z * Vector3::UnitZ();
    }
  }
  r.col(0) = pA;
  r.col(n) = pB;
  // (the catenary's points) => the chain's own equilibrium, when it has one near them
  if (const Eigen::Matrix3Xd guess = r; !lumpedLineStatics(line, r)) r = guess;
  std::vector<LumpedNodeBody> out;
  for (int i = 1; i < n; ++i) {
    const double ln = line.nodeLength(i);
    out.push_back({lumpedNodeName(name, i),
                   p.massPerLength * ln + p.waterDensity * area * ln * p.can, r.col(i)});
  }
  return out;
}

LumpedLineProvider::LumpedLineProvider(std::string name, const dynamics::Model& model,
                                       const Attachment& anchor, const Attachment& fairlead,
                                       std::shared_ptr<const LumpedLine> line,
                                       std::shared_ptr<Winch> winch)
    : ForceProvider(std::move(name)),
      anchor_(anchor),
      fairlead_(fairlead),
      line_(std::move(line)),
      winch_(std::move(winch)),
      gravity_(model.gravity) {
  auto bad = [&](const std::string& what) {
    throw std::invalid_argument("lumped line '" + this->name() + "': " + what);
  };
  if (winch_.get() != line_->winch()) bad("the winch given is not the line's own");
  for (const Attachment* a : {&anchor_, &fairlead_})
    if (a->body < 0 || a->body >= model.nbodies || !a->p_B.allFinite())
      bad("an end is on a body outside the model or not finite");
  const int n = line_->properties().segments;
  bodies_.assign(static_cast<std::size_t>(n + 1), -1);
  idxQ_.assign(bodies_.size(), -1);
  idxV_.assign(bodies_.size(), -1);
  masses_.assign(bodies_.size(), 0.0);
  for (int i = 1; i < n; ++i) {
    // (node body) => a translation joint from the world at the world origin
    const std::string node = lumpedNodeName(this->name(), i);
    const int b = model.bodyIndex(node);
    if (b < 1) bad("the model has no body '" + node + "' for its node " + std::to_string(i));
    const auto& X = model.X_PJ[static_cast<std::size_t>(b)];
    if (model.joints[b].type != dynamics::JointType::Translation || model.parent[b] != 0 ||
        !X.p.isZero() || !X.R.isIdentity())
      bad("body '" + node + "' must hang from the world on a translation joint at its origin");
    bodies_[static_cast<std::size_t>(i)] = b;
    idxQ_[static_cast<std::size_t>(i)] = model.idxQ[b];
    idxV_[static_cast<std::size_t>(i)] = model.idxV[b];
    masses_[static_cast<std::size_t>(i)] = model.inertias[b].mass;
  }
}

std::unique_ptr<ProviderScratch> LumpedLineProvider::makeScratch() const {
  auto w = std::make_unique<Scratch>();
  const int nodes = line_->nodes();
  for (Eigen::Matrix3Xd* m : {&w->r, &w->v, &w->f, &w->fc}) m->setZero(3, nodes);
  w->tension.setZero(nodes - 1);
  return w;
}

void LumpedLineProvider::gather(const Stage& s, Scratch& w) const {
  // (ends on their bodies, inner nodes from q and v) => r, v
  const int n = line_->properties().segments;
  w.r.col(0) = dynamics::pointPosition(s.data, anchor_.body, anchor_.p_B);
  w.v.col(0) = dynamics::pointVelocity(s.data, anchor_.body, anchor_.p_B);
  w.r.col(n) = dynamics::pointPosition(s.data, fairlead_.body, fairlead_.p_B);
  w.v.col(n) = dynamics::pointVelocity(s.data, fairlead_.body, fairlead_.p_B);
  for (int i = 1; i < n; ++i) {
    w.r.col(i) = s.q.segment<3>(idxQ_[static_cast<std::size_t>(i)]);
    w.v.col(i) = s.v.segment<3>(idxV_[static_cast<std::size_t>(i)]);
  }
}

LumpedLineProvider::Scratch& LumpedLineProvider::evaluated(
    const Stage& s, std::unique_ptr<ProviderScratch>& temporary) const {
  Scratch& w = scratchOf<Scratch>(s, temporary);
  gather(s, w);
  line_->nodeForces(w.r, w.v, s.t, w.f, w.tension);
  return w;
}

void LumpedLineProvider::doEvaluate(const Stage& s, dynamics::ExternalForces& f,
                                    Eigen::VectorXd& tau) const {
  std::unique_ptr<ProviderScratch> temporary;
  const Scratch& w = evaluated(s, temporary);
  const int n = line_->properties().segments;
  // (inner nodes) => node force minus the model's gravity on the node, as joint forces
  for (int i = 1; i < n; ++i)
    tau.segment<3>(idxV_[static_cast<std::size_t>(i)]) +=
        w.f.col(i) - masses_[static_cast<std::size_t>(i)] * gravity_;
  // (ends) => on their bodies at the points
  if (anchor_.body != 0) f.addPointForceWorld(anchor_.body, w.r.col(0), w.f.col(0));
  if (fairlead_.body != 0) f.addPointForceWorld(fairlead_.body, w.r.col(n), w.f.col(n));
}

double LumpedLineProvider::doPotentialEnergy(const Stage& s) const {
  std::unique_ptr<ProviderScratch> temporary;
  Scratch& w = scratchOf<Scratch>(s, temporary);
  gather(s, w);
  double e = line_->potentialEnergy(w.r, s.t);
  for (int i = 1; i < line_->properties().segments; ++i)
    e += masses_[static_cast<std::size_t>(i)] * gravity_.dot(w.r.col(i));
  return e;
}

double LumpedLineProvider::doPower(const Stage& s) const {
  // (node forces, their conservative part) => sum (f - f_c) . v, plus under a winch its dV/dt and
  // the kinetic energy of the rope leaving or joining the inner nodes, 1/2 m_i' |v_i|^2
  std::unique_ptr<ProviderScratch> temporary;
  Scratch& w = evaluated(s, temporary);
  line_->conservativeForces(w.r, s.t, w.fc);
  double power = ((w.f - w.fc).cwiseProduct(w.v)).sum();
  if (!winch_) return power;
  power += line_->potentialEnergyRate(w.r, s.t);
  for (int i = 1; i < line_->properties().segments; ++i)
    power += 0.5 * nodeMassRate(i, s.t) * w.v.col(i).squaredNorm();
  return power;
}

double LumpedLineProvider::fairleadTension(const Stage& s) const {
  std::unique_ptr<ProviderScratch> temporary;
  return evaluated(s, temporary).f.col(line_->properties().segments).norm();
}

double LumpedLineProvider::horizontalTension(const Stage& s) const {
  std::unique_ptr<ProviderScratch> temporary;
  const Vector3 f = evaluated(s, temporary).f.col(line_->properties().segments);
  return std::hypot(f.x(), f.y());
}

double LumpedLineProvider::anchorTension(const Stage& s) const {
  std::unique_ptr<ProviderScratch> temporary;
  return evaluated(s, temporary).tension[0];
}

double LumpedLineProvider::laidLength(const Stage& s) const {
  const LumpedLineProperties& p = line_->properties();
  if (!p.seabed) return 0.0;
  std::unique_ptr<ProviderScratch> temporary;
  Scratch& w = scratchOf<Scratch>(s, temporary);
  gather(s, w);
  // (a node within its diameter of the bed) => its unstretched length lies on it
  double laid = 0.0;
  const double l = line_->segmentLength(s.t);
  for (int i = 0; i <= p.segments; ++i)
    if (onBed(w.r, i)) laid += line_->nodeLength(i, l);
  return laid;
}

double LumpedLineProvider::fairleadAngle(const Stage& s) const {
  // (f_N) => its angle below the horizontal
  std::unique_ptr<ProviderScratch> temporary;
  const Vector3 f = evaluated(s, temporary).f.col(line_->properties().segments);
  return std::atan2(-f.z(), std::hypot(f.x(), f.y()));
}

double LumpedLineProvider::anchorAngle(const Stage& s) const {
  // (f_0, the bed under the anchor) => its angle above the horizontal
  std::unique_ptr<ProviderScratch> temporary;
  const Scratch& w = evaluated(s, temporary);
  const Vector3 f = w.f.col(0);
  const double up = onBed(w.r, 0) ? std::max(0.0, f.z()) : f.z();
  return std::atan2(up, std::hypot(f.x(), f.y()));
}

LumpedLineProvider::Touchdown LumpedLineProvider::touchdown(const Stage& s) const {
  // (nodes from the anchor) => the last of those on the bed without a gap
  std::unique_ptr<ProviderScratch> temporary;
  Scratch& w = scratchOf<Scratch>(s, temporary);
  gather(s, w);
  int k = 0;
  while (k < line_->properties().segments && onBed(w.r, 0) && onBed(w.r, k + 1)) ++k;
  const Vector3 d = w.r.col(k) - w.r.col(0);
  return {std::hypot(d.x(), d.y()), w.r.col(k)};
}

std::uint64_t LumpedLineProvider::accelerationJacobian(const Stage& s,
                                                       std::vector<dynamics::Matrix3>& dadr,
                                                       std::vector<dynamics::Matrix3>& dadv) const {
  // (node forces' blocks) => the inner nodes' rows over their masses at t
  std::unique_ptr<ProviderScratch> temporary;
  Scratch& w = scratchOf<Scratch>(s, temporary);
  gather(s, w);
  const std::uint64_t signature = line_->forceJacobian(w.r, w.v, s.t, dadr, dadv);
  const int width = 2 * line_->jacobianBandwidth() + 1;  // blocks per node row
  for (int i = 1; i < line_->properties().segments; ++i) {
    const double m = nodeMass(i, s.t);
    for (int k = width * i; k < width * i + width; ++k) {
      dadr[static_cast<std::size_t>(k)] /= m;
      dadv[static_cast<std::size_t>(k)] /= m;
    }
  }
  return signature;
}

}  // namespace yardsim::forces
