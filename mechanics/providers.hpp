#pragma once
// The force providers a multibody system's mechanics declare — its wire ropes and equalizers —
// built from their specs. One construction for the multibody model and for the stiffness
// estimate, so both see the same forces.
#include <memory>
#include <vector>

#include "forces/equalizer.hpp"
#include "forces/wire_rope.hpp"
#include "mechanics/description.hpp"

namespace yardsim::mechanics {

struct Providers {
  std::vector<std::unique_ptr<forces::WireRope>> ropes;
  std::vector<std::unique_ptr<forces::Equalizer>> equalizers;
};

// (rope material) => the provider's properties
forces::RopeProperties ropeProperties(const MechanicsSpec::Material& m);

// (mechanics, their model) => one provider per rope and per equalizer, in spec order
Providers makeProviders(const BuiltMechanics& mech, const dynamics::Model& model);

}  // namespace yardsim::mechanics
