#pragma once
// Loading a scene: the root YAML file and every file it includes, validated before anything is
// built. Every mistake of every file is collected (file:line:column, key path, what was
// expected, "did you mean"); the scene is returned only when there is none.
#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include <yaml-cpp/yaml.h>

#include "models/diagnostics.hpp"
#include "scene/scene.hpp"

namespace yardsim::scene {

using models::Diagnostics;

struct LoadResult {
  std::unique_ptr<Scene> scene;  // null when there were errors
  Diagnostics diagnostics;       // errors and warnings
  // wall s: files read and the instance tree built; the checks after it; the stiffness guard
  double readSeconds = 0.0, validationSeconds = 0.0, stiffnessSeconds = 0.0;
};

// A value given from outside for one of the root file's `params:` (a sweep case): where it was
// written, so a name the scene does not declare is reported there.
struct ParamOverride {
  YAML::Node value;
  SourceMark where;
  std::string keyPath;
};
using ParamOverrides = std::map<std::string, ParamOverride>;

// (root scene file) => the validated scene, or the diagnostics that refuse it
LoadResult loadScene(const std::filesystem::path& file);
// (root scene file, values replacing its root `params:`) => the validated scene, or the
// diagnostics that refuse it (an override of a parameter the root does not declare among them)
LoadResult loadScene(const std::filesystem::path& file, const ParamOverrides& overrides);

// (root scene file) => the validated scene; throws SceneError listing every diagnostic
std::unique_ptr<Scene> loadSceneOrThrow(const std::filesystem::path& file);

}  // namespace yardsim::scene
