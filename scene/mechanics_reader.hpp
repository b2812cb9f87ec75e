#pragma once
// The mechanics a `multibody` component (or a scene fragment's `mechanics:`) declares in YAML,
// parsed and checked with positions into a mechanics::MechanicsSpec (mechanics/description.hpp).
#include <functional>
#include <string>

#include <yaml-cpp/yaml.h>

#include "mechanics/description.hpp"
#include "models/params.hpp"

namespace yardsim::scene {

using mechanics::MechanicsSpec;
using models::Params;

// Where parsing reports a problem: (node, key path below the parameter, message, hint).
using MechanicsReport =
    std::function<void(const std::string& param, const YAML::Node& at, const std::string& key,
                       const std::string& message)>;

// (params gravity, bodies, loops, ropes, equalizers and, when present, loads, watch and the
// settings drive_bandwidth, drive_max_effort, drive_tolerance, equilibrium) => spec; every
// problem reported with its node
MechanicsSpec parseMechanics(const Params& params, const MechanicsReport& report);

}  // namespace yardsim::scene
