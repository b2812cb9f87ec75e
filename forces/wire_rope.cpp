#include "forces/wire_rope.hpp"

#include <stdexcept>

namespace yardsim::forces {

namespace {
// (parts, name) => parts, or std::invalid_argument
int checkedParts(int parts, const std::string& name) {
  if (parts < 1)
    throw std::invalid_argument("wire rope '" + name + "': the number of parts must be >= 1 (got " +
                                std::to_string(parts) + ")");
  return parts;
}
// (properties, name) => properties, checked
const RopeProperties& checked(const RopeProperties& p, const std::string& name) {
  checkRopeProperties(p, name);
  return p;
}
}  // namespace

WireRope::WireRope(std::string name, const dynamics::Model& model, std::vector<Attachment> path,
                   const RopeProperties& properties, int parts)
    : ForceProvider(std::move(name)),
      properties_(checked(properties, this->name())),
      parts_(checkedParts(parts, this->name())),
      path_(model, std::move(path), this->name()),
      winch_(properties.l0, properties.minLength) {}

RopeStrain WireRope::strain(const Stage& s, const PathMeasure& m) const {
  return {m.length, m.rate, winch_.length(s.t), winch_.rate(s.t)};
}

double WireRope::tension(const Stage& s) const {
  return ropeTension(properties_.ea, properties_.damping, strain(s, path_.measure(s.data)));
}

std::unique_ptr<ProviderScratch> WireRope::makeScratch() const {
  auto s = std::make_unique<Scratch>();
  s->points = path_.makePoints();
  return s;
}

void WireRope::doEvaluate(const Stage& s, dynamics::ExternalForces& f,
                          Eigen::VectorXd& /*tau*/) const {
  // (path, L0(t)) => T of one part; n T along the path on every point's body (a NaN T too, so
  // that evaluate() refuses it)
  std::unique_ptr<ProviderScratch> temporary;
  PathPoints& points = scratchOf<Scratch>(s, temporary).points;
  const RopeStrain e = strain(s, path_.update(s.data, points));
  const double tension = ropeTension(properties_.ea, properties_.damping, e);
  if (tension != 0.0) path_.applyTension(static_cast<double>(parts_) * tension, points, f);
}

double WireRope::doPotentialEnergy(const Stage& s) const {
  return static_cast<double>(parts_) *
         strainEnergy(properties_.ea, length(s), unstretchedLength(s.t));
}

double WireRope::doPower(const Stage& s) const {
  const RopeStrain e = strain(s, path_.measure(s.data));
  return ropePower(properties_.ea, ropeTension(properties_.ea, properties_.damping, e), parts_, e);
}

}  // namespace yardsim::forces
