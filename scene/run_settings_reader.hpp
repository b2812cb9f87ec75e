#pragma once
// The run settings of a scene's root file (docs/scenes.md): name, until (s), seed, the
// integrator block (method, dt in s, stiffness_check), record (interval in s, channel globs),
// report (plots, static levels in each channel's unit) and trace sinks; each problem reported
// at its node with the key path.
#include <string>

#include <yaml-cpp/yaml.h>

#include "models/diagnostics.hpp"
#include "scene/scene.hpp"

namespace yardsim::scene {

// (root document, its file) => the settings in s; problems in diags
void readRunSettings(Scene& s, const YAML::Node& doc, const std::string& file,
                     models::Diagnostics& diags);

}  // namespace yardsim::scene
