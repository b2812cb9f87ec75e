#pragma once
// Run-time modules: a library whose heavy dependency (OpenBLAS, FCL, libhdf5, Open MPI) is kept
// out of start-up lives in a module built and installed beside the layer's own library and is
// opened (dlopen) when first needed (cmake/YardsimTarget.cmake, yardsim_module). No units.
#include <string>

namespace yardsim::forces {

// (an address inside the calling library, module file name) => the module's path in the folder
// that library was loaded from (build tree and install tree alike), or the bare name if unknown
std::string moduleBeside(const void* anchor, const std::string& name);

// (module file, entry symbol, what it is and how to fix it for messages, global: its symbols
// visible to libraries it opens itself) => the entry's address, the module kept loaded for the
// process. Throws std::runtime_error naming the file and why (missing, not loadable, no entry).
void* openModuleEntry(const std::string& file, const char* entry, const std::string& what,
                      const std::string& fix, bool global = false);

}  // namespace yardsim::forces
