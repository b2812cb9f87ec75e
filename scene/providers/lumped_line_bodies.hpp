#pragma once
// The node bodies of a lumped-mass line (forces/lines/lumped_line_provider.hpp), shared by the
// readers that build one: `mooring:` with `model: lumped` and `ropes:` with `model: lumped`. Each
// inner node is a point mass on a translation joint from the world at the world origin (its q is
// its world position, m), placed at the chain's static equilibrium between the two ends at q0.
#include "forces/lines/lumped_line.hpp"
#include "forces/lines/lumped_line_provider.hpp"
#include "mechanics/description.hpp"

namespace yardsim::scene::providers {

// (a node: name, mass kg, world position m; the line's diameter, m) => its body: a point mass on a
// translation joint from the world, q0 its position, with a sphere of the diameter for the replay
mechanics::MechanicsSpec::Body lumpedNodeBody(const forces::LumpedNodeBody& node, double diameter);

// (the line's properties) => the ProviderSpec's bodies hook: (full name, the two ends' world
// points at q0) => the inner nodes' bodies, with a sphere of the line's diameter for the replay
mechanics::MechanicsSpec::ProviderBodies lumpedLineBodies(const forces::LumpedLineProperties& p);

}  // namespace yardsim::scene::providers
