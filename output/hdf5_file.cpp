#include "output/hdf5_file.hpp"

#include <dlfcn.h>

#include <stdexcept>

#include "output/hdf5_module.hpp"

namespace yardsim::output {

std::string hdf5ModulePath() {
#ifndef YARDSIM_HDF5_LINKED
  // (an address inside this library) => the file it was loaded from, and the module beside it
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&hdf5ModulePath), &info) == 0 || info.dli_fname == nullptr)
    return "libyardsim_hdf5.so";
  const std::filesystem::path module =
      std::filesystem::path(info.dli_fname).parent_path() / "libyardsim_hdf5.so";
  std::error_code error;
  const std::filesystem::path plain = std::filesystem::weakly_canonical(module, error);
  return (error ? module : plain).string();
#else
  return {};
#endif
}

Hdf5OpenEntry loadHdf5Module(const std::string& file) {
  const std::string fix =
      "; the HDF5 module is built and installed with yardsim (reinstall yardsim, or put the "
      "module back beside libyardsim_output.so)";
  if (!std::filesystem::is_regular_file(file))
    throw std::runtime_error("the HDF5 module " + file + " is missing" + fix);
  // (module) => loaded once for the process, never unloaded (libhdf5 keeps global state)
  void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* why = dlerror();
    throw std::runtime_error("the HDF5 module " + file + " cannot be loaded: " +
                             (why != nullptr ? why : "unknown error") + fix);
  }
  void* entry = dlsym(handle, "yardsim_hdf5_open");
  if (entry == nullptr)
    throw std::runtime_error("the HDF5 module " + file + " has no entry yardsim_hdf5_open" + fix);
  return reinterpret_cast<Hdf5OpenEntry>(entry);
}

Hdf5File::Hdf5File(const std::filesystem::path& file) {
#ifdef YARDSIM_HDF5_LINKED
  const Hdf5OpenEntry open = &yardsim_hdf5_open;
#else
  // (first HDF5 file of the process) => the module opened; a failure is thrown again next time
  static const Hdf5OpenEntry module = loadHdf5Module(hdf5ModulePath());
  const Hdf5OpenEntry open = module;
#endif
  open(file, writer_);
}

Hdf5File::~Hdf5File() = default;

void Hdf5File::group(const std::string& path) { writer_->group(path); }

void Hdf5File::doubles(const std::string& path, const std::vector<double>& v) {
  writer_->doubles(path, v);
}

void Hdf5File::integers(const std::string& path, const std::vector<std::int64_t>& v) {
  writer_->integers(path, v);
}

void Hdf5File::strings(const std::string& path, const std::vector<std::string>& v) {
  writer_->strings(path, v);
}

void Hdf5File::attribute(const std::string& path, const std::string& name,
                         const std::string& value) {
  writer_->attribute(path, name, value);
}

}  // namespace yardsim::output
