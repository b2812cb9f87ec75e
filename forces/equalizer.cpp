#include "forces/equalizer.hpp"

#include <stdexcept>

namespace yardsim::forces {

Equalizer::Equalizer(std::string name, const dynamics::Model& model, const Attachment& sheave,
                     const std::vector<std::vector<Attachment>>& branches,
                     const RopeProperties& properties)
    : ForceProvider(std::move(name)),
      properties_(properties),
      winch_(properties.l0, properties.minLength) {
  // (sheave, branches) => one path per branch starting at the sheave point
  checkRopeProperties(properties_, this->name());
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

PathMeasure Equalizer::measure(const Stage& s) const {
  PathMeasure m;
  for (const RopePath& b : branches_) {
    const PathMeasure mb = b.measure(s.data);
    m.length += mb.length;
    m.rate += mb.rate;
  }
  return m;
}

RopeStrain Equalizer::strain(const Stage& s, const PathMeasure& m) const {
  return {m.length, m.rate, winch_.length(s.t), winch_.rate(s.t)};
}

double Equalizer::tension(const Stage& s) const {
  return ropeTension(properties_.ea, properties_.damping, strain(s, measure(s)));
}

std::unique_ptr<ProviderScratch> Equalizer::makeScratch() const {
  auto s = std::make_unique<Scratch>();
  for (const RopePath& b : branches_) s->branches.push_back(b.makePoints());
  return s;
}

void Equalizer::doEvaluate(const Stage& s, dynamics::ExternalForces& f,
                           Eigen::VectorXd& /*tau*/) const {
  // (branch paths) => total length and rate => one tension T => T along every branch
  std::unique_ptr<ProviderScratch> temporary;
  std::vector<PathPoints>& points = scratchOf<Scratch>(s, temporary).branches;
  PathMeasure m;
  for (std::size_t j = 0; j < branches_.size(); ++j) {
    const PathMeasure mb = branches_[j].update(s.data, points[j]);
    m.length += mb.length;
    m.rate += mb.rate;
  }
  const double tension = ropeTension(properties_.ea, properties_.damping, strain(s, m));
  if (tension == 0.0) return;
  for (std::size_t j = 0; j < branches_.size(); ++j)
    branches_[j].applyTension(tension, points[j], f);
}

double Equalizer::doPotentialEnergy(const Stage& s) const {
  return strainEnergy(properties_.ea, length(s), unstretchedLength(s.t));
}

double Equalizer::doPower(const Stage& s) const {
  const RopeStrain e = strain(s, measure(s));
  return ropePower(properties_.ea, ropeTension(properties_.ea, properties_.damping, e), 1, e);
}

}  // namespace yardsim::forces
