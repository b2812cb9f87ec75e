#pragma once
// The STEP reader's OpenCASCADE code lives in a module, libyardsim_step.so, installed beside
// libyardsim_forces.so and opened (dlopen) the first time readStep is called, so a run that reads
// no STEP file never loads OCCT (its 60,000 symbol bindings cost 30-40 ms of start-up; see
// docs/performance.md). This header is the seam between the two: the module's one entry and the
// loader. Units and frames as in step_reader.hpp.
#include <string>

#include "forces/geometry/step_reader.hpp"

namespace yardsim::forces {

// (path, tolerance, model out) => the STEP file read into model; MeshError on failure
using StepReadEntry = void (*)(const std::string& path, const StepTolerance& tolerance,
                               StepModel& model);

// () => the module this build loads: libyardsim_step.so in the folder libyardsim_forces.so was
// loaded from (build tree and install tree alike); empty in a build without STEP support
std::string stepModulePath();

// (module file) => its entry `yardsim_step_read`, the module kept loaded for the process.
// Throws MeshError naming the file and why (missing, not loadable, no entry) and how to fix it.
StepReadEntry loadStepModule(const std::string& file);

}  // namespace yardsim::forces

// (path, tolerance, model out) => the entry itself, defined by step_module.cpp
extern "C" void yardsim_step_read(const std::string& path,
                                  const yardsim::forces::StepTolerance& tolerance,
                                  yardsim::forces::StepModel& model);
