#pragma once
// (validated scene) => the DEVS model: a coupled model per coupled instance, an atomic per
// atomic instance (made through the registry), the couplings. Only what the scene names is
// built. The root's name is hidden, so model paths are scene paths ("crane1.hoist1").
#include <memory>

#include "devs/coupled.hpp"
#include "scene/scene.hpp"

namespace yardsim::scene {

std::unique_ptr<devs::Coupled> assemble(const Scene& scene);

}  // namespace yardsim::scene
