#pragma once
// A crane rope with mass: a `ropes:` entry with `model: lumped` (docs/lines.md, "Crane ropes with
// mass"). It is the lumped-mass line of the mooring lines (forces/lines/lumped_line.hpp) between
// the two points of its path, or over the middle one of three (a sheave,
// forces/lines/lumped_rope_over_sheave.hpp), in air: n segments whose inner nodes are bodies of
// the system, stepped by the scene's integrator (forces/lines/lumped_line_provider.hpp). SI
// units, world frame.
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "mechanics/description.hpp"
#include "scene/spec_reader.hpp"

namespace yardsim::scene::providers {

// (a `ropes:` entry, the reader, its key path, the block's spec so far: its gravity) => false for
// a massless rope (no `model`, or `model: massless`; another value is reported at its node);
// true for `model: lumped`, the rope then added to spec.providers as a provider of kind `ropes`
// with its node bodies and channels ({path: 2 or 3 points, EA, L0, mass_per_length, diameter,
// segments, damping | damping_ratio, EI, min_length (2 points: its winch's)}), or its problems
// reported at their nodes
bool readLumpedRope(const spec::Reader& r, const YAML::Node& n, const std::string& key,
                    mechanics::MechanicsSpec& spec);

}  // namespace yardsim::scene::providers
