#pragma once
// A crane rope with mass: a `ropes:` entry with `model: lumped` (docs/lines.md, "Crane ropes with
// mass"). It is the lumped-mass line of the mooring lines (forces/lines/lumped_line.hpp) between
// the two points of its path, or over the middle one of three (a sheave,
// forces/lines/lumped_rope_over_sheave.hpp), in air: n segments whose inner nodes are bodies of
// the system, stepped by the scene's integrator (forces/lines/lumped_line_provider.hpp). SI
// units, world frame.
#include <optional>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "dynamics/spatial.hpp"
#include "mechanics/description.hpp"
#include "scene/spec_reader.hpp"

namespace yardsim::scene::providers {

// the keys of a `ropes:` entry with `model: lumped`
const std::vector<std::string>& lumpedRopeKeys();

// (the entry, the reader, its key path, its path read (2 or 3 points), the block's gravity, m/s^2)
// => the rope as a provider of kind `ropes` with its node bodies and channels ({EA, L0,
// mass_per_length, diameter, segments, damping | damping_ratio}); nullopt after a problem
// reported at its node
std::optional<mechanics::MechanicsSpec::ProviderSpec> readLumpedRope(
    const spec::Reader& r, const YAML::Node& n, const std::string& key,
    const std::vector<mechanics::MechanicsSpec::Point>& path, const dynamics::Vector3& gravity);

}  // namespace yardsim::scene::providers
