#pragma once
// Run-time modules of the upper layers (libhdf5, Open MPI): the loader of forces/module_loader.hpp,
// which the layers below use for theirs (OpenBLAS, FCL). forces/geometry/step_module.hpp keeps its
// own for OCCT.
#include "forces/module_loader.hpp"

namespace yardsim::output {

using forces::moduleBeside;
using forces::openModuleEntry;

}  // namespace yardsim::output
