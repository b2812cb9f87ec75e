#include "forces/lines/lumped_rope_over_sheave.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dynamics/kinematics.hpp"

namespace yardsim::forces {

using dynamics::Vector3;

int firstSpanSegments(int n, const Vector3& a, const Vector3& s, const Vector3& b) {
  // (distances from the sheave) => span A's share of the n - 1 segments off the sheave
  const double da = (a - s).norm(), db = (b - s).norm();
  const double share = da + db > 0.0 ? da / (da + db) : 0.5;
  return std::clamp(static_cast<int>(std::lround(share * n - 0.5)), 1, n - 2);
}

std::string sheaveNodeName(const std::string& rope, bool first, int spanASegments) {
  return first ? lumpedNodeName(rope + ".a", spanASegments) : lumpedNodeName(rope + ".b", 0);
}

LumpedRopeOverSheave::LumpedRopeOverSheave(std::string name, const dynamics::Model& model,
                                           const Attachment& first, const Attachment& sheave,
                                           const Attachment& last,
                                           std::shared_ptr<const LumpedLine> spanA,
                                           std::shared_ptr<const LumpedLine> spanB, double damping)
    : ForceProvider(std::move(name)), gravity_(model.gravity) {
  const double l = spanA->segmentLength();
  if (std::abs(spanB->segmentLength() / l - 1.0) > 1e-12)
    throw std::invalid_argument("lumped rope '" + this->name() +
                                "': its spans' segments must have one length");
  // (p, q) => the bodies that end the spans next to the sheave
  for (int k = 0; k < 2; ++k) {
    const std::string node = sheaveNodeName(this->name(), k == 0, spanA->properties().segments);
    const int b = model.bodyIndex(node);
    if (b < 1 || model.joints[b].type != dynamics::JointType::Translation || model.parent[b] != 0 ||
        !model.X_PJ[static_cast<std::size_t>(b)].p.isZero() ||
        !model.X_PJ[static_cast<std::size_t>(b)].R.isIdentity())
      throw std::invalid_argument("lumped rope '" + this->name() + "': no node body '" + node +
                                  "' on a translation joint from the world at its origin");
    pq_[static_cast<std::size_t>(k)] = b;
    mass_[static_cast<std::size_t>(k)] = model.inertias[b].mass;
  }
  halfWeight_ = 0.5 * spanA->weightPerLength() * l;
  const Attachment p{pq_[0], Vector3::Zero()}, q{pq_[1], Vector3::Zero()};
  spanA_ = std::make_unique<LumpedLineProvider>(this->name() + ".a", model, first, p, spanA);
  spanB_ = std::make_unique<LumpedLineProvider>(this->name() + ".b", model, q, last, spanB);
  RopeProperties over;
  over.ea = spanA->properties().ea;
  over.l0 = l;
  over.minLength = l;
  over.damping = damping;
  sheave_ = std::make_unique<Rope>(this->name() + ".sheave", model,
                                   std::vector<Attachment>{p, sheave, q}, over);
}

std::unique_ptr<ProviderScratch> LumpedRopeOverSheave::makeScratch() const {
  auto w = std::make_unique<Scratch>();
  w->a = spanA_->makeScratch();
  w->b = spanB_->makeScratch();
  w->sheave = sheave_->makeScratch();
  return w;
}

Stage LumpedRopeOverSheave::sub(const Stage& s, Scratch& w, int piece) {
  Stage out = s;
  out.scratch = piece == 0 ? w.a.get() : piece == 1 ? w.b.get() : w.sheave.get();
  return out;
}

void LumpedRopeOverSheave::doEvaluate(const Stage& s, dynamics::ExternalForces& f,
                                      Eigen::VectorXd& tau) const {
  std::unique_ptr<ProviderScratch> temporary;
  Scratch& w = scratchOf<Scratch>(s, temporary);
  spanA_->evaluate(sub(s, w, 0), f, tau);
  spanB_->evaluate(sub(s, w, 1), f, tau);
  sheave_->evaluate(sub(s, w, 2), f, tau);
  // (p, q) => the model's gravity on their mass replaced by the sheave half segment's net weight
  for (std::size_t k = 0; k < 2; ++k) {
    const int b = pq_[k];
    tau.segment<3>(s.model.idxV[b]) += -mass_[k] * gravity_ - halfWeight_ * Vector3::UnitZ();
  }
}

double LumpedRopeOverSheave::doPotentialEnergy(const Stage& s) const {
  // (spans, sheave segment's strain) + (p, q: the half segment's net weight, minus the model's
  // gravity potential of their mass, which the model counts)
  std::unique_ptr<ProviderScratch> temporary;
  Scratch& w = scratchOf<Scratch>(s, temporary);
  double e = spanA_->potentialEnergy(sub(s, w, 0)) + spanB_->potentialEnergy(sub(s, w, 1)) +
             sheave_->potentialEnergy(sub(s, w, 2));
  for (std::size_t k = 0; k < 2; ++k) {
    const Vector3 r = s.q.segment<3>(s.model.idxQ[pq_[k]]);
    e += halfWeight_ * r.z() + mass_[k] * gravity_.dot(r);
  }
  return e;
}

double LumpedRopeOverSheave::doPower(const Stage& s) const {
  std::unique_ptr<ProviderScratch> temporary;
  Scratch& w = scratchOf<Scratch>(s, temporary);
  return spanA_->power(sub(s, w, 0)) + spanB_->power(sub(s, w, 1)) + sheave_->power(sub(s, w, 2));
}

double LumpedRopeOverSheave::sheaveTension(const Stage& s) const {
  std::unique_ptr<ProviderScratch> temporary;
  Scratch& w = scratchOf<Scratch>(s, temporary);
  return sheave_->tension(sub(s, w, 2));
}

}  // namespace yardsim::forces
