#pragma once
#include <memory>
#include <string>

#include "scene/scene.hpp"

namespace yardsim::cli {

// (scene file) => the validated scene, or nullptr once every error is printed to stderr;
// warnings are printed either way
std::unique_ptr<scene::Scene> loadAndReport(const std::string& file);

}  // namespace yardsim::cli
