#pragma once
// Loading a scene: the root YAML file and every file it includes, validated before anything is
// built. Every mistake of every file is collected (file:line:column, key path, what was
// expected, "did you mean"); the scene is returned only when there is none.
#include <filesystem>
#include <memory>

#include "models/diagnostics.hpp"
#include "scene/scene.hpp"

namespace yardsim::scene {

using models::Diagnostics;

struct LoadResult {
  std::unique_ptr<Scene> scene;  // null when there were errors
  Diagnostics diagnostics;       // errors and warnings
};

// (root scene file) => the validated scene, or the diagnostics that refuse it
LoadResult loadScene(const std::filesystem::path& file);

// (root scene file) => the validated scene; throws SceneError listing every diagnostic
std::unique_ptr<Scene> loadSceneOrThrow(const std::filesystem::path& file);

}  // namespace yardsim::scene
