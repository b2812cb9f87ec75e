#pragma once
// The scene's `integrator:` block: {method, dt, alpha, rho_inf, rtol, atol, max_order, max_step,
// newton_tol, max_newton, loops, baumgarte_alpha, baumgarte_beta} into a dynamics::IntegratorSpec
// (dynamics/integrators/factory.hpp; docs/integrators.md), with every mistake reported at its
// file:line:column: unknown keys and methods (with "did you mean"), values out of range; a key
// the chosen method does not use is a warning.
#include <string>

#include <yaml-cpp/yaml.h>

#include "dynamics/integrators/factory.hpp"
#include "models/diagnostics.hpp"

namespace yardsim::scene {

using models::Diagnostics;

// (integrator mapping, file) => spec without its dt (0); problems into diags. dt is the caller's
// to read and check (scene/run_settings_reader.cpp: a positive number of seconds; the scene's
// mechanics ask for it when absent, mechanical_systems.cpp).
dynamics::IntegratorSpec parseIntegratorSpec(const YAML::Node& node, const std::string& file, Diagnostics& diags);

}  // namespace yardsim::scene
