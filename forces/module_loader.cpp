#include "forces/module_loader.hpp"

#include <dlfcn.h>

#include <filesystem>
#include <stdexcept>

namespace yardsim::forces {

std::string moduleBeside(const void* anchor, const std::string& name) {
  // (an address inside the library) => the file it was loaded from, and the module beside it
  Dl_info info{};
  if (dladdr(anchor, &info) == 0 || info.dli_fname == nullptr) return name;
  // (the loader's path, e.g. bin/../lib/libyardsim_output.so) => without the detours
  const std::filesystem::path module = std::filesystem::path(info.dli_fname).parent_path() / name;
  std::error_code error;
  const std::filesystem::path plain = std::filesystem::weakly_canonical(module, error);
  return (error ? module : plain).string();
}

void* openModuleEntry(const std::string& file, const char* entry, const std::string& what,
                      const std::string& fix, bool global) {
  if (!std::filesystem::is_regular_file(file))
    throw std::runtime_error(what + " " + file + " is missing" + fix);
  // (module) => loaded once for the process, never unloaded (its libraries keep global state)
  void* handle = dlopen(file.c_str(), RTLD_NOW | (global ? RTLD_GLOBAL : RTLD_LOCAL));
  if (handle == nullptr) {
    const char* why = dlerror();
    throw std::runtime_error(
        what + " " + file + " cannot be loaded: " + (why != nullptr ? why : "unknown error") + fix);
  }
  void* address = dlsym(handle, entry);
  if (address == nullptr)
    throw std::runtime_error(what + " " + file + " has no entry " + entry + fix);
  return address;
}

}  // namespace yardsim::forces
