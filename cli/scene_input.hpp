#pragma once
#include <memory>
#include <string>

#include "models/diagnostics.hpp"
#include "run/profile.hpp"
#include "scene/scene.hpp"

namespace yardsim::cli {

// (scene file) => the validated scene, or nullptr once every error is printed to stderr;
// warnings are printed either way (and copied into `warnings` when given: a run lists them
// among its alarms); the read, validation and stiffness guard times go to `times`
std::unique_ptr<scene::Scene> loadAndReport(const std::string& file,
                                            run::PhaseTimes* times = nullptr,
                                            std::vector<models::Diagnostic>* warnings = nullptr);

// (output folder) => created if need be and checked writable (a file is created and removed in
// it); false once the reason is printed to stderr (the caller exits with status 1)
bool prepareOutputFolder(const std::string& outdir);

}  // namespace yardsim::cli
