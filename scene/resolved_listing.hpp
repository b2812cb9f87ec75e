#pragma once
// `yardsim validate --print-resolved`: exactly what a scene will run — every coupled and
// atomic instance with its type and resolved parameters, every coupling by full port path,
// the recorder and trace sinks, the run settings — and nothing else.
#include <string>

#include "scene/scene.hpp"

namespace yardsim::scene {

std::string resolvedListing(const Scene& scene);

}  // namespace yardsim::scene
