#include "forces/rope.hpp"

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

Rope::Rope(std::string name, const dynamics::Model& model, std::vector<Attachment> path,
           const RopeProperties& properties, int parts)
    : ForceProvider(std::move(name)),
      kind_("wire rope"),
      properties_(checked(properties, this->name())),
      parts_(checkedParts(parts, this->name())),
      winch_(properties.l0, properties.minLength) {
  branches_.emplace_back(model, std::move(path), this->name());
}

Rope::Rope(std::string name, const dynamics::Model& model, const Attachment& sheave,
           const std::vector<std::vector<Attachment>>& branches, const RopeProperties& properties)
    : ForceProvider(std::move(name)),
      kind_("equalizer"),
      properties_(checked(properties, this->name())),
      parts_(1),
      winch_(properties.l0, properties.minLength) {
  // (sheave, branches) => one path per branch starting at the sheave point
  if (branches.size() < 2)
    throw std::invalid_argument("equalizer '" + this->name() +
                                "': needs at least 2 branches (got " +
                                std::to_string(branches.size()) + ")");
  branches_.reserve(branches.size());
  for (std::size_t j = 0; j < branches.size(); ++j) {
    if (branches[j].empty())
      throw std::invalid_argument("equalizer '" + this->name() + "': branch " + std::to_string(j) +
                                  " has no end attachment");
    std::vector<Attachment> points;
    points.reserve(branches[j].size() + 1);
    points.push_back(sheave);
    points.insert(points.end(), branches[j].begin(), branches[j].end());
    branches_.emplace_back(model, std::move(points),
                           this->name() + "' branch '" + std::to_string(j));
  }
}

PathMeasure Rope::measure(const Stage& s) const {
  // (branches) => the first one's length and rate, plus the others'
  PathMeasure m = branches_.front().measure(s.data);
  for (std::size_t j = 1; j < branches_.size(); ++j) {
    const PathMeasure mb = branches_[j].measure(s.data);
    m.length += mb.length;
    m.rate += mb.rate;
  }
  return m;
}

RopeStrain Rope::strain(const Stage& s, const PathMeasure& m) const {
  return {m.length, m.rate, winch_.length(s.t), winch_.rate(s.t)};
}

double Rope::tension(const Stage& s) const {
  return ropeTension(properties_.ea, properties_.damping, strain(s, measure(s)));
}

std::unique_ptr<ProviderScratch> Rope::makeScratch() const {
  auto s = std::make_unique<Scratch>();
  for (const RopePath& b : branches_) s->branches.push_back(b.makePoints());
  return s;
}

void Rope::doEvaluate(const Stage& s, dynamics::ExternalForces& f, Eigen::VectorXd& /*tau*/) const {
  // (branch paths, L0(t)) => total length and rate => T of one part => n T along every branch
  // on every point's body (a NaN T too, so that evaluate() refuses it)
  std::unique_ptr<ProviderScratch> temporary;
  std::vector<PathPoints>& points = scratchOf<Scratch>(s, temporary).branches;
  PathMeasure m = branches_.front().update(s.data, points.front());
  for (std::size_t j = 1; j < branches_.size(); ++j) {
    const PathMeasure mb = branches_[j].update(s.data, points[j]);
    m.length += mb.length;
    m.rate += mb.rate;
  }
  const double tension = ropeTension(properties_.ea, properties_.damping, strain(s, m));
  if (tension == 0.0) return;
  const double pull = static_cast<double>(parts_) * tension;
  for (std::size_t j = 0; j < branches_.size(); ++j) branches_[j].applyTension(pull, points[j], f);
}

double Rope::doPotentialEnergy(const Stage& s) const {
  return static_cast<double>(parts_) *
         strainEnergy(properties_.ea, length(s), unstretchedLength(s.t));
}

double Rope::doPower(const Stage& s) const {
  const RopeStrain e = strain(s, measure(s));
  return ropePower(properties_.ea, ropeTension(properties_.ea, properties_.damping, e), parts_, e);
}

}  // namespace yardsim::forces
