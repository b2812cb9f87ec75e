#include "mechanics/providers.hpp"

namespace yardsim::mechanics {

forces::RopeProperties ropeProperties(const MechanicsSpec::Material& m) {
  forces::RopeProperties props;
  props.ea = m.ea;
  props.l0 = m.l0;
  props.damping = m.damping;
  props.minLength = m.minLength;
  if (m.mbl > 0) props.breakingLoad = m.mbl;
  return props;
}

Providers makeProviders(const BuiltMechanics& mech, const dynamics::Model& model) {
  // (spec point) => attachment on the body of that name
  auto attach = [&](const MechanicsSpec::Point& p) {
    return forces::Attachment{model.bodyIndex(p.first), p.second};
  };
  Providers out;
  for (const auto& r : mech.ropes) {
    std::vector<forces::Attachment> path;
    for (const auto& p : r.path) path.push_back(attach(p));
    out.ropes.push_back(std::make_unique<forces::Rope>(r.name, model, path,
                                                           ropeProperties(r.material), r.parts));
  }
  for (const auto& e : mech.equalizers) {
    std::vector<std::vector<forces::Attachment>> branches;
    for (const auto& b : e.branches) {
      branches.emplace_back();
      for (const auto& p : b) branches.back().push_back(attach(p));
    }
    out.ropes.push_back(std::make_unique<forces::Rope>(
        e.name, model, attach(e.sheave), branches, ropeProperties(e.material)));
  }
  return out;
}

}  // namespace yardsim::mechanics
