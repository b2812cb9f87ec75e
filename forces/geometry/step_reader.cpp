#include "forces/geometry/step_reader.hpp"

#include <dlfcn.h>

#include <filesystem>

#include "forces/geometry/step_module.hpp"

namespace yardsim::forces {

std::string stepModulePath() {
#if defined(YARDSIM_WITH_STEP) && !defined(YARDSIM_STEP_LINKED)
  // (an address inside this library) => the file it was loaded from, and the module beside it
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&stepModulePath), &info) == 0 || info.dli_fname == nullptr)
    return "libyardsim_step.so";
  // (the loader's path, e.g. bin/../lib/../lib/libyardsim_forces.so) => without the detours
  const std::filesystem::path module =
      std::filesystem::path(info.dli_fname).parent_path() / "libyardsim_step.so";
  std::error_code error;
  const std::filesystem::path plain = std::filesystem::weakly_canonical(module, error);
  return (error ? module : plain).string();
#else
  return {};
#endif
}

StepReadEntry loadStepModule(const std::string& file) {
  const std::string fix =
      "; the STEP reader module is built and installed with yardsim when it is configured with "
      "-DYARDSIM_WITH_STEP=ON (reinstall yardsim, or put the module back beside "
      "libyardsim_forces.so)";
  if (!std::filesystem::is_regular_file(file))
    throw MeshError("the STEP reader module " + file + " is missing" + fix);
  // (module) => loaded once for the process, never unloaded (OCCT keeps global state)
  void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* why = dlerror();
    throw MeshError("the STEP reader module " + file +
                    " cannot be loaded: " + (why != nullptr ? why : "unknown error") + fix);
  }
  void* entry = dlsym(handle, "yardsim_step_read");
  if (entry == nullptr)
    throw MeshError("the STEP reader module " + file + " has no entry yardsim_step_read" + fix);
  return reinterpret_cast<StepReadEntry>(entry);
}

StepModel readStep(const std::string& path, const StepTolerance& tolerance) {
#ifdef YARDSIM_WITH_STEP
  if (!std::filesystem::is_regular_file(path))
    throw MeshError(path + ": cannot open the STEP file");
  if (!(tolerance.chord > 0) || !(tolerance.angle > 0))
    throw MeshError(path + ": the tessellation's chord and angle tolerances must be > 0");
#ifdef YARDSIM_STEP_LINKED
  const StepReadEntry read = &yardsim_step_read;
#else
  // (first STEP file of the process) => the module opened; a failure is thrown again next time
  static const StepReadEntry module = loadStepModule(stepModulePath());
  const StepReadEntry read = module;
#endif
  StepModel model;
  read(path, tolerance, model);
  checkClosedMesh(model.mesh);
  return model;
#else
  (void)tolerance;
  throw MeshError(path +
                  ": this yardsim was built without STEP support; configure it with "
                  "-DYARDSIM_WITH_STEP=ON (Debian packages libocct-data-exchange-dev and "
                  "libocct-modeling-algorithms-dev)");
#endif
}

bool stepSupported() {
#ifdef YARDSIM_WITH_STEP
  return true;
#else
  return false;
#endif
}

}  // namespace yardsim::forces
