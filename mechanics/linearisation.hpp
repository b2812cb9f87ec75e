#pragma once
// The forces with an analytic linearisation (forces/provider_linearisation.hpp: quasi-static
// catenary lines) wired to the kernel's finite-difference Jacobians
// (AccelerationSource::beginLinearisation): the implicit methods' Newton matrices (dense and
// coloured, HHT and generalized-alpha, CVODE and ARKODE) and the stiffness estimate then hold
// those forces' analytic derivatives and solve no catenary per column.
#include "forces/provider_linearisation.hpp"
#include "mechanics/data.hpp"
#include "mechanics/system.hpp"

namespace yardsim::mechanics {

// (provider) => its analytic linearisation, or that of the provider it wraps with its channels,
// or nullptr
const forces::ProviderLinearisation* linearisationOf(const forces::ForceProvider& p);

// (system, its data: the providers' scratch) => the kernel's linearisation callback set when some
// provider has one (else none: the kernel's linearises() stays false); data must outlive it
void connectLinearisation(const System& s, Data& d);

}  // namespace yardsim::mechanics
