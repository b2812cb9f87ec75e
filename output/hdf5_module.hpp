#pragma once
// The HDF5 writer's libhdf5 code lives in a module, libyardsim_hdf5.so, installed beside
// libyardsim_output.so and opened (dlopen) the first time an HDF5 file is written, so a run that
// writes none never loads libhdf5 and what it pulls in (libcurl, TLS, Kerberos, LDAP: about 40
// libraries whose symbol bindings cost most of a run's start-up; docs/performance.md). This
// header is the seam between the two: the writer's interface, the module's one entry and the
// loader. Paths and types as in hdf5_file.hpp.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace yardsim::output {

// One open HDF5 file (libhdf5's C API behind it, in the module).
class Hdf5Backend {
 public:
  virtual ~Hdf5Backend() = default;
  // (path) => the group and its parents
  virtual void group(const std::string& path) = 0;
  // (path, values) => a dataset of float64 / int64 / variable-length UTF-8 strings
  virtual void doubles(const std::string& path, const std::vector<double>& values) = 0;
  virtual void integers(const std::string& path, const std::vector<std::int64_t>& values) = 0;
  virtual void strings(const std::string& path, const std::vector<std::string>& values) = 0;
  // (object path, name, value) => a string attribute on a group or dataset
  virtual void attribute(const std::string& path, const std::string& name,
                         const std::string& value) = 0;
};

// (file, writer out) => the file created (truncated) and its writer in out; throws
// std::runtime_error naming the file when it cannot be
using Hdf5OpenEntry = void (*)(const std::filesystem::path& file,
                               std::unique_ptr<Hdf5Backend>& writer);

// () => the module this build loads: libyardsim_hdf5.so in the folder libyardsim_output.so was
// loaded from (build tree and install tree alike); empty in a static build (linked in)
std::string hdf5ModulePath();

// (module file) => its entry `yardsim_hdf5_open`, the module kept loaded for the process.
// Throws std::runtime_error naming the file and why (missing, not loadable, no entry).
Hdf5OpenEntry loadHdf5Module(const std::string& file);

}  // namespace yardsim::output

// (file, writer out) => the entry itself, defined by hdf5_module.cpp
extern "C" void yardsim_hdf5_open(const std::filesystem::path& file,
                                  std::unique_ptr<yardsim::output::Hdf5Backend>& writer);
