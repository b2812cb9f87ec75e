#include <stdexcept>

#include "forces/hydro/lapack_module.hpp"
#include "forces/module_loader.hpp"

namespace yardsim::forces::hydro {

std::string lapackModulePath() {
#ifdef YARDSIM_LAPACK_LINKED
  return {};
#else
  return moduleBeside(reinterpret_cast<const void*>(&lapackModulePath), "libyardsim_lapack.so");
#endif
}

const LapackRoutines& loadLapackModule(const std::string& file) {
  using Entry = const LapackRoutines* (*)();
  const auto entry = reinterpret_cast<Entry>(openModuleEntry(
      file, "yardsim_lapack_routines", "the LAPACK module",
      "; the LAPACK module is built and installed with yardsim and needs OpenBLAS (Debian "
      "package libopenblas0; reinstall yardsim, or put the module back beside "
      "libyardsim_forces.so)"));
  return *entry();
}

const LapackRoutines& lapack() {
#ifdef YARDSIM_LAPACK_LINKED
  return *yardsim_lapack_routines();
#else
  // (first dense solve of the process) => the module opened; a failure is thrown again next time
  static const LapackRoutines& routines = loadLapackModule(lapackModulePath());
  return routines;
#endif
}

}  // namespace yardsim::forces::hydro
