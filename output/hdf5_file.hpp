#pragma once
// A small HDF5 writer on Debian's libhdf5 (C API): groups, 1-D datasets of doubles, 64-bit
// integers and variable-length UTF-8 strings, and string attributes — what h5py and HDFView
// read without yardsim. Paths are absolute ("/table/status"); parent groups are created.
// libhdf5 is loaded with the first file written (hdf5_module.hpp).
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace yardsim::output {

class Hdf5Backend;

class Hdf5File {
 public:
  // (file) => created (truncated); throws std::runtime_error naming the file when it cannot be,
  // or why the HDF5 module cannot be loaded
  explicit Hdf5File(const std::filesystem::path& file);
  ~Hdf5File();
  Hdf5File(const Hdf5File&) = delete;
  Hdf5File& operator=(const Hdf5File&) = delete;

  // (path) => the group and its parents
  void group(const std::string& path);
  // (path, values) => a dataset of float64 / int64 / variable-length strings
  void doubles(const std::string& path, const std::vector<double>& values);
  void integers(const std::string& path, const std::vector<std::int64_t>& values);
  void strings(const std::string& path, const std::vector<std::string>& values);
  // (object path, name, value) => a string attribute on a group or dataset
  void attribute(const std::string& path, const std::string& name, const std::string& value);

 private:
  std::unique_ptr<Hdf5Backend> writer_;
};

}  // namespace yardsim::output
