#include "output/hdf5_file.hpp"

#include "output/hdf5_module.hpp"
#include "output/module_loader.hpp"

namespace yardsim::output {

std::string hdf5ModulePath() {
#ifndef YARDSIM_HDF5_LINKED
  return moduleBeside(reinterpret_cast<const void*>(&hdf5ModulePath), "libyardsim_hdf5.so");
#else
  return {};
#endif
}

Hdf5OpenEntry loadHdf5Module(const std::string& file) {
  return reinterpret_cast<Hdf5OpenEntry>(openModuleEntry(
      file, "yardsim_hdf5_open", "the HDF5 module",
      "; the HDF5 module is built and installed with yardsim (reinstall yardsim, or put the "
      "module back beside libyardsim_output.so)"));
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

void Hdf5File::group(const std::string& path) {
  writer_->group(path);
}

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
