#pragma once
// The force providers a multibody system's mechanics declare — its ropes: the wire ropes, then
// the equalizers, one forces::Rope each — built from their specs. One construction for the
// multibody model and for the stiffness estimate, so both see the same forces.
#include <memory>
#include <vector>

#include "forces/rope.hpp"
#include "forces/rope.hpp"
#include "mechanics/description.hpp"

namespace yardsim::mechanics {

struct Providers {
  // mech.ropes in spec order, then mech.equalizers in spec order
  std::vector<std::unique_ptr<forces::Rope>> ropes;
};

// (rope material) => the provider's properties
forces::RopeProperties ropeProperties(const MechanicsSpec::Material& m);

// (mechanics, their model) => one rope per wire rope and per equalizer, in that order
Providers makeProviders(const BuiltMechanics& mech, const dynamics::Model& model);

}  // namespace yardsim::mechanics
