#pragma once
// Checks of the assembled coupling graph (Boost.Graph), after a scene's couplings are valid:
// zero-delay algebraic loops (a cycle of models that each answer an input at the same time)
// are errors naming the cycle's models; atomic input ports that nothing feeds are warnings.
#include "models/diagnostics.hpp"
#include "models/scene.hpp"

namespace yardsim::models {

void checkCouplingGraph(const Instance& root, Diagnostics& diags);

}  // namespace yardsim::models
